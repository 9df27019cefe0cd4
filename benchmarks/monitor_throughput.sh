#!/usr/bin/env bash
# SPDX-License-Identifier: EPL-2.0
# Throughput and latency of the runtime monitor's whole pipeline (decode, EMF update, footprint geometry, Drools
# queries, transition rules, signals) on one core, without a router: a synthetic stream replayed at full speed.
# 20 Hz state messages, 50 moving humans, a full frame listing every static obstacle each simulated second (the
# monitor steps over the static entries whose bytes equal the last applied ones: see docs/monitor.md "Full frames").
# Usage: benchmarks/monitor_throughput.sh [CORE]     (builds runtime-monitor/target/rei-monitor.jar if missing)
# Targets (issue 4): >= 10,000 updates/s and p99 < 1 ms at 100 objects; >= 2,000 updates/s at 10,000 objects.
# Wall-clock latency includes preemption by other processes on the same core; the CPU line is the pipeline
# thread's own CPU time per update. The exit code is 1 when a target is missed on the wall clock.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
JAR="$ROOT/runtime-monitor/target/rei-monitor.jar"
CORE="${1:-0}"
if [[ ! -f "$JAR" ]]; then
  (cd "$ROOT" && mvn -B -q -s .mvn/settings.xml -pl runtime-monitor -am package -DskipTests)
fi
echo "== rei-monitor throughput on core $CORE of $(nproc) (load before: $(cut -d' ' -f1-3 /proc/loadavg))"
status=0
run() { # objects states warmup
  taskset -c "$CORE" java -XX:+UseParallelGC -Xms1g -Xmx3g -cp "$JAR" org.rei.monitor.cli.Bench "$1" "$2" "$3" \
    2>/dev/null | grep -E "^(RESULT|CPU|signals)"
}
check() { # line min_rate max_p99_us
  local rate p99
  rate=$(sed -E 's/.*updates_per_s=([0-9]+).*/\1/' <<<"$1")
  p99=$(sed -E 's/.*p99_us=([0-9.]+).*/\1/' <<<"$1")
  if (( rate < $2 )) || [[ -n "$3" && $(awk -v a="$p99" -v b="$3" 'BEGIN{print (a>=b)}') == 1 ]]; then
    echo "   MISSED target (>= $2 updates/s${3:+, p99 < $3 us})"; status=1
  else
    echo "   met target (>= $2 updates/s${3:+, p99 < $3 us})"
  fi
}
out=$(run 100 20000 10000);   echo "$out"; check "$(grep RESULT <<<"$out")" 10000 1000
out=$(run 1000 20000 10000);  echo "$out"; check "$(grep RESULT <<<"$out")" 2000 ""
out=$(run 10000 6000 3000);   echo "$out"; check "$(grep RESULT <<<"$out")" 2000 ""
echo "== load after: $(cut -d' ' -f1-3 /proc/loadavg)"
exit $status

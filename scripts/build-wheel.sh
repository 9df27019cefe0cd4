#!/usr/bin/env bash
# SPDX-License-Identifier: EPL-2.0
#
# scripts/build-wheel.sh [-o DIR] [--jars ROLE,...] — builds REI's wheel (rei-VERSION-py3-none-any.whl) carrying
# the jars a machine without this checkout needs: by default the monitor's, which a Ray worker node replays every
# run in (docs/campaigns.md#setting-up-a-cluster), and the people server (pedestrians/jupedsim_server.py) that moves
# reactive people there with the JuPedSim of the node's $REI_PEOPLE_PYTHON. ROLEs are the keys of JARS in sim-adapter/src/rei/toolchain.py
# (cli, language-server, room-editor, monitor, sut-kit). The jars must be built (./rei builds them).
#
# The wheel is built from a copy of sim-adapter/ with the jars in src/rei/jars/ (the checkout itself never holds
# them there), by pip with build isolation (setuptools from PyPI, as `pip install -e sim-adapter` gets it). It
# holds REI's code and jars only: its requirements (pyproject.toml's dependencies; Ray with the campaign-ray
# extra) are pip's to install on the node, and the WAMP router (Crossbar.io, only for `mode: pipeline` and external
# SUTs) goes into a virtual environment of its own there, as scripts/setup-router.sh makes one here.
# Prints the wheel's path on its last line.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="$ROOT/target/wheel"
ROLES="monitor"
while [ $# -gt 0 ]; do
    case "$1" in
        -o) OUT="$2"; shift 2 ;;
        --jars) ROLES="$2"; shift 2 ;;
        *) echo "usage: scripts/build-wheel.sh [-o DIR] [--jars ROLE,...]" >&2; exit 2 ;;
    esac
done
PYTHON="$ROOT/.venv/bin/python"
[ -x "$PYTHON" ] || { echo "build-wheel: no $PYTHON; run ./rei once" >&2; exit 1; }

STAGE="$(mktemp -d)"
trap 'rm -rf "$STAGE"' EXIT
mkdir -p "$STAGE/src" "$OUT"
cp "$ROOT/sim-adapter/pyproject.toml" "$ROOT/sim-adapter/README.md" "$STAGE/"
# the package's sources only: no byte code or egg-info of the checkout's editable install
(cd "$ROOT/sim-adapter/src" && find rei -name __pycache__ -prune -o -name '*.egg-info' -prune -o -type f -print0 \
    | xargs -0 cp --parents -t "$STAGE/src")
mkdir -p "$STAGE/src/rei/jars"
IFS=, read -r -a roles <<<"$ROLES"
for role in "${roles[@]}"; do
    # the jar's path as rei.toolchain knows it, so the two never disagree
    jar="$("$PYTHON" -c 'import sys; from rei.toolchain import JARS; print(JARS[sys.argv[1]])' "$role" 2>/dev/null)" \
        || { echo "build-wheel: unknown jar role '$role'" >&2; exit 2; }
    [ -f "$ROOT/$jar" ] || { echo "build-wheel: $jar is missing: run ./rei once to build the Java parts" >&2; exit 1; }
    cp "$ROOT/$jar" "$STAGE/src/rei/jars/"
done
# the people server (EPL-2.0 OR GPL-2.0-or-later; it alone imports JuPedSim, in a Python of its own on the node:
# docs/people.md), found by rei.sim.people.server as the package's data
mkdir -p "$STAGE/src/rei/pedestrians"
cp "$ROOT/pedestrians/jupedsim_server.py" "$STAGE/src/rei/pedestrians/"
rm -f "$OUT"/rei-*.whl
PIP_NO_INPUT=1 "$PYTHON" -m pip wheel --quiet --disable-pip-version-check --no-deps -w "$OUT" "$STAGE" >&2
wheel="$(ls "$OUT"/rei-*.whl)"
# every wheel is rei 0.1.0: one built from uncommitted changes is told from the committed tree only by its contents
# (a node's REI must be the driver's build, which rei campaign/search check at connect time)
dirty="$(git -C "$ROOT" status --porcelain -- sim-adapter/src pedestrians/jupedsim_server.py 2>/dev/null || true)"
if [ -n "$dirty" ]; then
    echo "build-wheel: warning: built from uncommitted changes ($(printf '%s\n' "$dirty" | wc -l) file(s), e.g." \
         "$(printf '%s\n' "$dirty" | head -1 | cut -c4-)): the wheel holds them as they are now; nodes must run the" \
         "driver's build (docs/campaigns.md#setting-up-a-cluster)" >&2
fi
echo "build-wheel: $wheel ($(du -h "$wheel" | cut -f1), jars: $ROLES)" >&2
echo "$wheel"

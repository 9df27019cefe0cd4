#!/usr/bin/env bash
# SPDX-License-Identifier: EPL-2.0
#
# scripts/build-eclipse.sh [--skip-tests] — build REI's Eclipse plug-in, its feature and the p2 update site
# (releng/org.rei.site/target/org.rei.site-VERSION.zip) with Tycho, and run the plug-in's workbench test.
#
# The Eclipse reactor (releng/pom.xml) is separate from the main build: Tycho needs Maven 3.9 (releng/mvnw
# downloads it from Maven Central) and the Eclipse platform it targets needs Java 21 or newer. Everything it
# needs comes from Maven Central. The plug-in ships the main build's language server and generator jars, so
# those are built first when missing or out of date.
#
# The workbench test opens a real Eclipse window: it uses $DISPLAY when set, else a virtual X server
# (xvfb-run, installed with apt-get when missing and running as root).
#
# Environment:
#   REI_ECLIPSE_JAVA_HOME  a JDK 21+ for the Tycho build (default: the first found in /usr/lib/jvm)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
# shellcheck source=../rei
source "$ROOT/rei"

say() { echo "build-eclipse: $*" >&2; }
die() { say "error: $*"; exit 1; }

skip_tests=false
case "${1:-}" in
    "") ;;
    --skip-tests) skip_tests=true ;;
    *) die "unknown argument '$1' (usage: scripts/build-eclipse.sh [--skip-tests])" ;;
esac

java_major() { "$1/bin/java" -XshowSettings:properties -version 2>&1 | sed -n 's/^ *java.specification.version = //p'; }

eclipse_java_home() {
    local candidate
    for candidate in "${REI_ECLIPSE_JAVA_HOME:-}" "${JAVA_HOME:-}" /usr/lib/jvm/*; do
        [ -n "$candidate" ] && [ -x "$candidate/bin/javac" ] || continue
        if [ "$(java_major "$candidate")" -ge 21 ] 2>/dev/null; then
            echo "$candidate"
            return 0
        fi
    done
    return 1
}

java_home="$(eclipse_java_home)" || die "no JDK 21 or newer found (the Eclipse platform needs it): install one" \
    "(e.g. apt-get install openjdk-21-jdk-headless) or set REI_ECLIPSE_JAVA_HOME"
say "Tycho runs on $java_home (Java $(java_major "$java_home"))"

# The main build's jars, which the plug-in ships.
rei_check_java
if rei_java_outdated; then
    rei_build_java
fi

maven_args=(-B -s "$ROOT/.mvn/settings.xml" -f "$ROOT/releng/pom.xml" verify)
runner=()
if $skip_tests; then
    maven_args+=(-DskipTests)
elif [ -z "${DISPLAY:-}" ]; then
    if ! command -v xvfb-run >/dev/null 2>&1; then
        [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1 \
            || die "the workbench test needs a display: set DISPLAY, or install xvfb (apt-get install xvfb)," \
                   "or pass --skip-tests"
        say "installing xvfb with apt-get (a virtual display for the workbench test)"
        export DEBIAN_FRONTEND=noninteractive
        apt-get install -y --no-install-recommends xvfb xauth >/dev/null \
            || { apt-get update >/dev/null && apt-get install -y --no-install-recommends xvfb xauth >/dev/null; }
    fi
    runner=(xvfb-run -a -s "-screen 0 1280x1024x24")
fi

start=$SECONDS
JAVA_HOME="$java_home" "${runner[@]}" "$ROOT/releng/mvnw" "${maven_args[@]}"
site="$(ls "$ROOT"/releng/org.rei.site/target/org.rei.site-*.zip)"
say "p2 update site: ${site#"$ROOT"/} ($(du -k "$site" | cut -f1) KiB), built in $((SECONDS - start)) s"
if ! $skip_tests; then
    say "workbench screenshot: bundles/org.rei.eclipse.tests/target/screenshots/eclipse-markers.png"
fi

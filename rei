#!/usr/bin/env bash
# SPDX-License-Identifier: EPL-2.0
#
# ./rei ARGS...  — bootstrap the checkout when needed, then run `.venv/bin/rei ARGS...`.
#
# The bootstrap is a fast no-op when everything is up to date (no JVM start, no network):
#   1. checks java >= 17 (always: every command needs it), mvn and python3 >= 3.11 (only when they are about to
#      be used, so a built checkout runs without Maven);
#   2. builds the Java parts (`mvn install -DskipTests`) when a jar is missing or a source file under the Java
#      module folders is newer than the last build;
#   3. creates .venv and installs sim-adapter[dev] when .venv is missing or sim-adapter/pyproject.toml changed;
#   4. runs scripts/setup-router.sh (WAMP router in .venv-router) when it exists;
#   5. runs scripts/setup-people.sh (JuPedSim for the reactive people, in .venv-people) when it exists.
#
# Sourcing this file (as ./run-tests does) only defines the functions; `rei_bootstrap --no-java-build` skips
# step 2 for callers that run the full Maven build themselves.
#
# Environment: REI_PYTHON (interpreter that creates .venv, default python3), JAVA_HOME (as for Maven).

REI_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

# Jars the Python side starts; keep in step with JARS in sim-adapter/src/rei/toolchain.py.
REI_JARS=(
    "generators/org.rei.cli/target/rei-cli.jar"
    "bundles/org.rei.dsl.ide/target/rei-language-server.jar"
    "bundles/org.rei.dsl.edit/target/rei-room-editor.jar"
    "runtime-monitor/target/rei-monitor.jar"
    "sut-kits/java/target/rei-sut-kit.jar"
)
# Folders whose sources go into the jars; target/ and generated folders inside them are ignored.
# (bundles/org.rei.eclipse* belong to the Eclipse reactor in releng/, which this build does not run)
REI_JAVA_SOURCES=(maps metamodels bundles/org.rei.dsl bundles/org.rei.dsl.ide bundles/org.rei.dsl.edit generators queries cep warm-jvm wamp-auth runtime-monitor sut-kits)
# Written after every successful Java build: a build that changes no jar (only a README changed) still counts.
REI_JAVA_STAMP="target/rei-bootstrap/java-build.stamp"
REI_VENV_STAMP=".venv/.rei-pyproject.sha256"

rei_say() { echo "rei: $*" >&2; }
rei_die() { echo "rei: error: $*" >&2; exit 1; }

# The feature version of a java launcher: the JDK's release file when present (no JVM start), else -version.
rei_java_version() {
    local java="$1" real release version
    real="$(readlink -f "$(command -v "$java")" 2>/dev/null || true)"
    release="${real%/bin/java}/release"
    if [ -n "$real" ] && [ -f "$release" ]; then
        version="$(sed -n 's/^JAVA_VERSION="\([^"]*\)".*/\1/p' "$release")"
    fi
    if [ -z "${version:-}" ]; then
        version="$("$java" -version 2>&1 | sed -n 's/.*version "\([^"]*\)".*/\1/p' | head -n 1)"
    fi
    case "$version" in
        1.*) version="${version#1.}" ;;
    esac
    echo "${version%%[.+_-]*}"
}

rei_check_java() {
    local java="java" version
    if [ -n "${JAVA_HOME:-}" ]; then
        java="$JAVA_HOME/bin/java"
        [ -x "$java" ] || rei_die "JAVA_HOME=$JAVA_HOME has no bin/java; fix JAVA_HOME or unset it"
    elif ! command -v java >/dev/null 2>&1; then
        rei_die "java not found; install a Java 17+ JDK (e.g. apt-get install openjdk-17-jdk-headless)"
    fi
    version="$(rei_java_version "$java")"
    case "$version" in
        '' | *[!0-9]*) rei_die "cannot read the version of $java" ;;
    esac
    [ "$version" -ge 17 ] || rei_die "$java is Java $version; REI needs Java 17 or newer (set JAVA_HOME)"
}

rei_check_mvn() {
    command -v mvn >/dev/null 2>&1 || rei_die "mvn not found; install Maven 3.8+ (e.g. apt-get install maven)"
}

# Prints the python3 >= 3.11 to create .venv with.
rei_find_python() {
    local python="${REI_PYTHON:-python3}"
    command -v "$python" >/dev/null 2>&1 || rei_die "$python not found; install Python 3.11+ (or set REI_PYTHON)"
    "$python" -c 'import sys; sys.exit(sys.version_info < (3, 11))' \
        || rei_die "$python is Python $("$python" -c 'import platform; print(platform.python_version())'); REI needs 3.11+ (set REI_PYTHON)"
    "$python" -c 'import venv, ensurepip' 2>/dev/null \
        || rei_die "$python cannot create virtual environments; install its venv module (e.g. apt-get install python3-venv)"
    echo "$python"
}

# Succeeds when the Java parts must be (re)built; says why.
rei_java_outdated() {
    local jar newest=""
    for jar in "${REI_JARS[@]}"; do
        [ -f "$REI_ROOT/$jar" ] || { rei_say "missing $jar"; return 0; }
        if [ -z "$newest" ] || [ "$REI_ROOT/$jar" -nt "$newest" ]; then newest="$REI_ROOT/$jar"; fi
    done
    if [ -f "$REI_ROOT/$REI_JAVA_STAMP" ] && [ "$REI_ROOT/$REI_JAVA_STAMP" -nt "$newest" ]; then
        newest="$REI_ROOT/$REI_JAVA_STAMP"
    fi
    local dirs=() dir changed
    for dir in "${REI_JAVA_SOURCES[@]}"; do
        [ -d "$REI_ROOT/$dir" ] && dirs+=("$REI_ROOT/$dir")
    done
    changed="$(find "$REI_ROOT/pom.xml" "${dirs[@]}" \
        \( -name target -o -name emf-gen -o -name xtext-gen -o -name xtend-gen -o -name src-gen \
           -o -name node_modules -o -name .settings -o -name bin \) -prune \
        -o -type f -newer "$newest" -print -quit 2>/dev/null)"
    if [ -n "$changed" ]; then
        rei_say "${changed#"$REI_ROOT"/} changed since the last build"
        return 0
    fi
    return 1
}

rei_build_java() {
    rei_check_mvn
    local log="$REI_ROOT/target/rei-bootstrap/java-build.log"
    mkdir -p "$(dirname "$log")"
    rei_say "building Java parts (first run takes a few minutes; log in ${log#"$REI_ROOT"/})..."
    # The code generators log at INFO whatever -q says: keep the log, show its end only on failure.
    if ! (cd "$REI_ROOT" && mvn -B -q -Dstyle.color=never -s .mvn/settings.xml install -DskipTests) >"$log" 2>&1; then
        tail -n 40 "$log" >&2
        rei_die "the Java build failed; the whole log is in $log"
    fi
    rei_java_stamp
}

rei_java_stamp() {
    mkdir -p "$REI_ROOT/$(dirname "$REI_JAVA_STAMP")" && touch "$REI_ROOT/$REI_JAVA_STAMP"
}

rei_setup_venv() {
    local want have python
    want="$(sha256sum "$REI_ROOT/sim-adapter/pyproject.toml" | cut -d' ' -f1)"
    have="$(cat "$REI_ROOT/$REI_VENV_STAMP" 2>/dev/null || true)"
    if [ -x "$REI_ROOT/.venv/bin/rei" ] && [ "$want" = "$have" ]; then
        return 0
    fi
    if [ ! -x "$REI_ROOT/.venv/bin/python" ]; then
        python="$(rei_find_python)" || exit 1
        rei_say "creating .venv with $("$python" -V 2>&1)..."
        "$python" -m venv "$REI_ROOT/.venv" || rei_die "could not create .venv"
    fi
    rei_say "installing the Python package (sim-adapter) into .venv..."
    (cd "$REI_ROOT" && PIP_NO_INPUT=1 .venv/bin/python -m pip install -q --disable-pip-version-check \
        -e 'sim-adapter[dev]') || rei_die "pip install -e 'sim-adapter[dev]' failed"
    echo "$want" >"$REI_ROOT/$REI_VENV_STAMP"
}

rei_setup_router() {
    local script="$REI_ROOT/scripts/setup-router.sh" log
    [ -f "$script" ] || return 0
    if [ -x "$REI_ROOT/.venv-router/bin/crossbar" ]; then
        # Installed: the script only confirms the version; keep quiet unless it fails.
        log="$(bash "$script" 2>&1)" || { echo "$log" >&2; rei_die "scripts/setup-router.sh failed"; }
    else
        rei_say "installing the WAMP router into .venv-router (first run takes a few minutes)..."
        bash "$script" || rei_die "scripts/setup-router.sh failed"
    fi
}

rei_setup_people() {
    local script="$REI_ROOT/scripts/setup-people.sh" log
    [ -f "$script" ] || return 0
    if [ -x "$REI_ROOT/.venv-people/bin/python" ]; then
        log="$(bash "$script" 2>&1)" || { echo "$log" >&2; rei_die "scripts/setup-people.sh failed"; }
    else
        rei_say "installing JuPedSim (reactive people) into .venv-people..."
        bash "$script" || rei_die "scripts/setup-people.sh failed"
    fi
}

# rei_bootstrap [--no-java-build]
rei_bootstrap() {
    rei_check_java
    if [ "${1:-}" != "--no-java-build" ] && rei_java_outdated; then
        rei_build_java
    fi
    rei_setup_venv
    rei_setup_router
    rei_setup_people
}

if [ "${BASH_SOURCE[0]}" = "$0" ]; then
    set -euo pipefail
    rei_bootstrap
    exec "$REI_ROOT/.venv/bin/rei" "$@"
fi

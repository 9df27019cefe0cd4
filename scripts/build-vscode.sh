#!/usr/bin/env bash
# SPDX-License-Identifier: EPL-2.0
#
# scripts/build-vscode.sh — build, test and package the VS Code extension of editors/vscode as
# editors/vscode/dist/rei-VERSION.vsix, with the language server and the generator jars inside it.
#
# Needs: the two jars of the Maven build (built beforehand: see the message below), Node.js 20+ with npm and the
# npm registry (npm ci installs exactly package-lock.json), Java 17+ for the tests, which start the real jars,
# and python3. Exits non-zero when any step fails: the tests, and the check that the packaged extension loads.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ext="$root/editors/vscode"
# The jars the extension ships in server/: the language server (editor features) and the CLI (Generate artifacts).
jars=(
    "bundles/org.rei.dsl.ide/target/rei-language-server.jar"
    "generators/org.rei.cli/target/rei-cli.jar"
)

say() { echo "build-vscode: $*" >&2; }
die() { say "error: $*"; exit 1; }

missing=()
for jar in "${jars[@]}"; do
    [ -f "$root/$jar" ] || missing+=("$jar")
done
if [ "${#missing[@]}" -gt 0 ]; then
    die "missing ${missing[*]}: build the jars first, at the repository root:" \
        "mvn -B -s .mvn/settings.xml -q install -DskipTests   (or ./rei validate examples/simple_navigation.rei)"
fi
command -v node >/dev/null 2>&1 || die "node not found: install Node.js 20 or newer"
command -v python3 >/dev/null 2>&1 || die "python3 not found (it unpacks the .vsix for its check)"
command -v npm >/dev/null 2>&1 || die "npm not found: install it with Node.js 20 or newer"
node_major="$(node -p 'process.versions.node.split(".")[0]')"
[ "$node_major" -ge 20 ] || die "Node.js $(node --version) is too old: @vscode/vsce 3 needs Node.js 20 or newer"

cd "$ext"
start=$SECONDS

say "installing the locked npm packages (npm ci)"
npm ci --no-audit --no-fund --loglevel=error

say "compiling (tsc)"
rm -rf out # no compiled test of a deleted source lingers
npm run --silent compile

# Copied before the tests, so that they start the jars from where the packaged extension has them.
rm -rf server
mkdir server
for jar in "${jars[@]}"; do
    cp "$root/$jar" server/
done
# vsce wants a LICENSE beside package.json; the repository's one is the extension's.
cp "$root/LICENSE.md" LICENSE.md

say "testing (grammars, language server, generator)"
npm test

version="$(node -p 'require("./package.json").version')"
vsix="dist/rei-$version.vsix"
mkdir -p dist
rm -f "$vsix"
say "packaging $vsix"
# The extension has no public repository URL to name; without the flag vsce asks on the terminal.
npx --no-install vsce package --allow-missing-repository --out "$vsix"

# The package itself: unpacked outside editors/vscode (so nothing resolves from its node_modules), its main
# module must load with every dependency from inside it. Python's zipfile unpacks: REI needs python3 anyway.
unpacked="$(mktemp -d)"
trap 'rm -rf "$unpacked"' EXIT
python3 -m zipfile -e "$vsix" "$unpacked"
node out/test/check-vsix.js "$unpacked"

size="$(du -h "$vsix" | cut -f1)"
say "done in $((SECONDS - start)) s"
echo "$ext/$vsix ($size, $(stat -c %s "$vsix") bytes)"

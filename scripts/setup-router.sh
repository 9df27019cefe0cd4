#!/usr/bin/env bash
# SPDX-License-Identifier: EPL-2.0
#
# Installs the WAMP router (Crossbar.io) into its own virtual environment, <repo>/.venv-router.
#
# Why a separate venv: Crossbar pulls ~140 packages (~375 MB) with pins of its own (twisted, autobahn extras,
# cryptography, ...). The simulation venv (.venv) must stay small and free of those pins; the sim-adapter only
# starts the `crossbar` executable as a separate process (rei.wamp.router), it never imports it.
#
# Idempotent: when the venv already holds the pinned version, it exits at once without touching the network.
#
# Environment:
#   REI_CROSSBAR_VERSION  crossbar version to pin (default below)
#   REI_ROUTER_PYTHON     python interpreter for the venv (default: python3.11, then python3)
set -euo pipefail

CROSSBAR_VERSION="${REI_CROSSBAR_VERSION:-26.10.1}"
REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
VENV="${REPO_ROOT}/.venv-router"

installed_version() {
    # Reads the dist-info folder name: no interpreter start-up, no network; prints nothing when absent.
    local d
    for d in "${VENV}"/lib/python3*/site-packages/crossbar-*.dist-info; do
        [ -d "$d" ] || continue
        d="${d##*/crossbar-}"
        echo "${d%.dist-info}"
        return 0
    done
}

if [ -x "${VENV}/bin/crossbar" ] && [ "$(installed_version)" = "${CROSSBAR_VERSION}" ]; then
    echo "setup-router: crossbar ${CROSSBAR_VERSION} already installed in ${VENV}"
    exit 0
fi

PYTHON="${REI_ROUTER_PYTHON:-}"
if [ -z "${PYTHON}" ]; then
    for candidate in python3.11 python3; do
        if command -v "${candidate}" >/dev/null 2>&1; then PYTHON="${candidate}"; break; fi
    done
fi
if [ -z "${PYTHON}" ]; then
    echo "setup-router: no python3 interpreter found (set REI_ROUTER_PYTHON)" >&2
    exit 1
fi

echo "setup-router: installing crossbar==${CROSSBAR_VERSION} into ${VENV} with $(${PYTHON} -V 2>&1)"
if [ ! -x "${VENV}/bin/python" ]; then
    "${PYTHON}" -m venv "${VENV}"
fi
"${VENV}/bin/python" -m pip install --quiet --disable-pip-version-check --upgrade pip
"${VENV}/bin/python" -m pip install --quiet --disable-pip-version-check "crossbar==${CROSSBAR_VERSION}"

if [ "$(installed_version)" != "${CROSSBAR_VERSION}" ]; then
    echo "setup-router: installation finished but crossbar ${CROSSBAR_VERSION} is not in ${VENV}" >&2
    exit 1
fi
"${VENV}/bin/crossbar" version >/dev/null 2>&1 || {
    echo "setup-router: ${VENV}/bin/crossbar does not start; run '${VENV}/bin/crossbar version' to see why" >&2
    exit 1
}
echo "setup-router: crossbar ${CROSSBAR_VERSION} ready: ${VENV}/bin/crossbar"

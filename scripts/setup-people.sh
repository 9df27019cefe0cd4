#!/usr/bin/env bash
# SPDX-License-Identifier: EPL-2.0
#
# Installs JuPedSim, the pedestrian-dynamics library that moves REI's reactive people, into its own virtual
# environment, <repo>/.venv-people, beside the people server (pedestrians/jupedsim_server.py) that runs it.
#
# Why a separate venv and process: JuPedSim's wheel links parts of CGAL that are GPL-3.0-or-later, and REI's
# Python package must hold no GPL code (docs/people.md#licence-where-jupedsim-runs). REI's simulation therefore never imports it; it
# starts the server as a separate program and talks to it over a pipe, as it runs the WAMP router. The wheel also
# declares PySide6 and VTK for its visualizer (about 1.5 GB), which the simulation core does not use: JuPedSim is
# installed without them (--no-deps) and its run-time needs (numpy, shapely, deprecated) are named here.
#
# Idempotent: when the venv already holds the pinned version, it exits at once without touching the network.
#
# Environment:
#   REI_JUPEDSIM_VERSION  JuPedSim version to pin (default below)
#   REI_PEOPLE_PYTHON     python interpreter for the venv (default: python3.11, then python3)
set -euo pipefail

JUPEDSIM_VERSION="${REI_JUPEDSIM_VERSION:-1.4.2}"
REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
VENV="${REPO_ROOT}/.venv-people"
STAMP="${VENV}/.rei-jupedsim-${JUPEDSIM_VERSION}"

if [ -f "${STAMP}" ] && [ -x "${VENV}/bin/python" ]; then
    echo "setup-people: JuPedSim ${JUPEDSIM_VERSION} already installed in ${VENV}"
    exit 0
fi

PYTHON="${REI_PEOPLE_PYTHON:-}"
if [ -z "${PYTHON}" ]; then
    for candidate in python3.11 python3; do
        if command -v "${candidate}" >/dev/null 2>&1; then PYTHON="${candidate}"; break; fi
    done
fi
if [ -z "${PYTHON}" ]; then
    echo "setup-people: no python3 interpreter found (set REI_PEOPLE_PYTHON)" >&2
    exit 1
fi

echo "setup-people: installing jupedsim==${JUPEDSIM_VERSION} into ${VENV} with $(${PYTHON} -V 2>&1)"
if [ ! -x "${VENV}/bin/python" ]; then
    "${PYTHON}" -m venv "${VENV}"
fi
pip() { PIP_NO_INPUT=1 "${VENV}/bin/python" -m pip --quiet --disable-pip-version-check "$@"; }
pip install "numpy~=2.2" "shapely~=2.0" "deprecated~=1.2.18" "msgpack>=1.0"
pip install --no-deps "jupedsim==${JUPEDSIM_VERSION}"
"${VENV}/bin/python" -c "import jupedsim, shapely, msgpack" || {
    echo "setup-people: jupedsim ${JUPEDSIM_VERSION} was installed into ${VENV} but does not import" >&2
    exit 1
}
touch "${STAMP}"
echo "setup-people: JuPedSim ${JUPEDSIM_VERSION} ready in ${VENV}"

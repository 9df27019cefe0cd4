#!/usr/bin/env bash
# SPDX-License-Identifier: EPL-2.0
#
# Installs a headless browser (Debian's `chromium`) for the report's end-to-end test
# (tests/report/test_report_in_browser.py renders OUT/report.html and takes a screenshot).
#
# Why the distribution's package: the test must run without internet access to browser download sites (no
# Playwright/Selenium-managed downloads), and apt's chromium is kept patched with the rest of the system.
#
# Idempotent: exits at once when a browser is already on PATH (or REI_CHROMIUM names one).
#
# Environment:
#   REI_CHROMIUM  browser executable to use instead of searching PATH
set -euo pipefail

for candidate in "${REI_CHROMIUM:-}" chromium chromium-browser google-chrome; do
    [ -n "${candidate}" ] || continue
    if command -v "${candidate}" >/dev/null 2>&1; then
        echo "setup-browser: $(command -v "${candidate}") already installed"
        exit 0
    fi
done

if [ "$(id -u)" -ne 0 ]; then
    echo "setup-browser: no headless browser found and not running as root." >&2
    echo "  Install one as root:  apt-get install -y chromium   (or set REI_CHROMIUM to a Chromium/Chrome binary)" >&2
    exit 1
fi
if ! command -v apt-get >/dev/null 2>&1; then
    echo "setup-browser: no apt-get here; install Chromium with your package manager or set REI_CHROMIUM" >&2
    exit 1
fi

echo "setup-browser: installing chromium with apt-get"
export DEBIAN_FRONTEND=noninteractive
if ! apt-get install -y --no-install-recommends chromium; then
    apt-get update
    apt-get install -y --no-install-recommends chromium
fi
echo "setup-browser: $(command -v chromium) installed"

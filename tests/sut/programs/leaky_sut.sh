#!/bin/sh
# SPDX-License-Identifier: EPL-2.0
# A wrapper (as a launch script would be) that starts a helper which ignores SIGTERM, then runs the reference
# navigation: when the navigation exits at the run's end, REI must still stop the helper left in the group.
python3 -c 'import signal, time; signal.signal(signal.SIGTERM, signal.SIG_IGN); time.sleep(3600)' "$1" &
exec rei nav-sut

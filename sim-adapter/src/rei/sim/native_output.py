# SPDX-License-Identifier: EPL-2.0
"""Silences what pybullet's C++ code prints straight to the process's stdout and stderr.

Its SDF importer warns "Couldn't parse vector3" for every valid ``<cylinder>`` and prints its build time on
connect; neither is actionable, and both would bury REI's own output. Python-level writes are unaffected
only in the sense that they are flushed before the redirection starts.
"""

from __future__ import annotations

import contextlib
import os
import sys
from collections.abc import Iterator


@contextlib.contextmanager
def quiet_native_output() -> Iterator[None]:
    """Redirect file descriptors 1 and 2 to /dev/null while the block runs."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(1), os.dup(2)]
    try:
        with open(os.devnull, "wb") as devnull:
            os.dup2(devnull.fileno(), 1)
            os.dup2(devnull.fileno(), 2)
            yield
    finally:
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        for fd in saved:
            os.close(fd)

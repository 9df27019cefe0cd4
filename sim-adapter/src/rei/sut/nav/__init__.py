# SPDX-License-Identifier: EPL-2.0
"""Reference navigation stack (``nav`` controller): grid A* global planner, DWA local planner, recovery."""

from rei.sut.nav.config import NavConfig
from rei.sut.nav.controller import NavController

__all__ = ["NavConfig", "NavController"]

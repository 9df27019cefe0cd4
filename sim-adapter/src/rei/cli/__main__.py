# SPDX-License-Identifier: EPL-2.0
"""`python -m rei.cli`: the console script without an installed entry point."""

import sys

from rei.cli import main

sys.exit(main())

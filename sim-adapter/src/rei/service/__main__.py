# SPDX-License-Identifier: EPL-2.0
"""``python -m rei.service``: the background service process (rei.service.daemon)."""

import sys

from rei.service.daemon import main

sys.exit(main())

# SPDX-License-Identifier: EPL-2.0
"""The live view: a page that watches a running mission straight from the WAMP router (docs/view.md).

The page itself is built from ``viewer/`` (TypeScript, Vite) into ``static/``, which ships with the package,
so viewing needs no Node.js. This package serves it with the run's configuration.
"""

from rei.view.config import FORMAT, RouterAuth, view_config
from rei.view.server import STATIC_DIR, ViewServer, ViewServerError

#: Seconds `rei run --view` waits for a page to subscribe before it starts the simulation anyway.
VIEWER_WAIT = 30.0

__all__ = ["FORMAT", "STATIC_DIR", "VIEWER_WAIT", "RouterAuth", "ViewServer", "ViewServerError", "view_config"]

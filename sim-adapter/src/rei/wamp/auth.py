# SPDX-License-Identifier: EPL-2.0
"""Credentials of REI's router roles (docs/security.md): generated per run, kept in files only the user reads.

Why files and not arguments or environment variables: a child's command line is readable by every user in
``/proc/PID/cmdline``; a file created with mode 0600 in a 0700 folder is readable by the user only. Each child gets
the path of its own role's file, so a component holds no other component's secret.
"""

from __future__ import annotations

import json
import os
import secrets
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

AuthMethod = Literal["wampcra", "ticket"]
#: Format tag of a credentials file.
FORMAT = "rei-router-credentials/1"


@dataclass(frozen=True, slots=True)
class Credentials:
    """What one client needs to join an authenticating router: its authid (= role) and secret."""

    authid: str
    secret: str
    method: AuthMethod = "wampcra"

    def __post_init__(self) -> None:
        if self.method not in ("wampcra", "ticket"):
            raise ValueError(f"authentication method {self.method!r}: expected wampcra or ticket")
        if not self.authid or not self.secret:
            raise ValueError("credentials need an authid and a secret")

    def __repr__(self) -> str:  # never print a secret into a log
        return f"Credentials(authid={self.authid!r}, method={self.method!r}, secret=***)"

    def answer(self, method: str, extra: Mapping[str, Any]) -> str:
        """The AUTHENTICATE signature for the router's CHALLENGE."""
        from autobahn.wamp import auth

        if method != self.method:
            raise ValueError(f"the router asks for {method}, these credentials are for {self.method}")
        if method == "ticket":
            return self.secret
        key: str | bytes = self.secret
        if "salt" in extra:
            key = auth.derive_key(self.secret, extra["salt"], extra.get("iterations", 1000), extra.get("keylen", 32))
        signature = auth.compute_wcs(key, extra["challenge"])
        return signature.decode("ascii") if isinstance(signature, bytes) else signature

    def to_json(self) -> dict[str, str]:
        return {"format": FORMAT, "authid": self.authid, "method": self.method, "secret": self.secret}


def new_secret() -> str:
    """256 random bits, URL-safe text."""
    return secrets.token_urlsafe(32)


def write_private(path: Path, text: str) -> None:
    """Write ``text`` to a new file that only the user can read (mode 0600 from creation on, never wider)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        path.unlink()
    except FileNotFoundError:
        pass
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o600)
    with os.fdopen(fd, "w", encoding="utf-8") as out:
        out.write(text)
    os.chmod(path, 0o600)  # in case the umask was stricter than needed; never wider


def write_credentials(path: Path, credentials: Credentials) -> Path:
    write_private(path, json.dumps(credentials.to_json(), indent=2) + "\n")
    return path


def load_credentials(path: str | os.PathLike[str]) -> Credentials:
    """Read a credentials file; refuses one that other users could read (ValueError, OSError)."""
    path = Path(path)
    mode = path.stat().st_mode & 0o777
    if mode & 0o077:
        raise ValueError(f"{path}: credentials readable by other users (mode {mode:o}); expected 600")
    data = json.loads(path.read_text(encoding="utf-8"))
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        raise ValueError(f"{path}: not a REI credentials file ({FORMAT})")
    return Credentials(str(data["authid"]), str(data["secret"]), data.get("method", "wampcra"))

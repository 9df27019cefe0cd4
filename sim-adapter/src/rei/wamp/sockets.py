# SPDX-License-Identifier: EPL-2.0
"""Diagnostics: TCP_NODELAY as another process's sockets really have it (docs/protocol.md, "Latency").

Why read it from the socket: whether Nagle's algorithm is off depends on code paths inside Crossbar, autobahn and
netty that configuration options do not reliably reach; the option on the live socket is the truth. pidfd_getfd(2)
(Linux >= 5.6, syscall 438 on every architecture) duplicates the other process's socket into this one; the kernel
allows it for a descendant (or with ptrace rights).
"""

from __future__ import annotations

import ctypes
import os
import socket

_PIDFD_GETFD = 438


def tcp_nodelay(pid: int, *, local_port: int | None = None, peer_port: int | None = None) -> list[int]:
    """TCP_NODELAY (0 or 1) of each connected TCP socket of process ``pid`` whose local port is ``local_port``
    (connections it accepted there) or whose peer port is ``peer_port`` (connections it made there)."""
    if (local_port is None) == (peer_port is None):
        raise ValueError("give exactly one of local_port and peer_port")
    libc = ctypes.CDLL(None, use_errno=True)
    pidfd = os.pidfd_open(pid)
    values = []
    try:
        for fd in os.listdir(f"/proc/{pid}/fd"):
            try:
                if not os.readlink(f"/proc/{pid}/fd/{fd}").startswith("socket:"):
                    continue
            except OSError:
                continue  # closed meanwhile
            dup = libc.syscall(_PIDFD_GETFD, pidfd, int(fd), 0)
            if dup < 0:
                raise OSError(ctypes.get_errno(), "pidfd_getfd")
            with socket.socket(fileno=dup) as sock:
                if sock.family not in (socket.AF_INET, socket.AF_INET6) or sock.type != socket.SOCK_STREAM:
                    continue
                try:
                    peer = sock.getpeername()  # connected sockets only, not a listening one
                except OSError:
                    continue
                port = sock.getsockname()[1] if local_port is not None else peer[1]
                if port == (local_port if local_port is not None else peer_port):
                    values.append(sock.getsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY))
    finally:
        os.close(pidfd)
    return values


__all__ = ["tcp_nodelay"]

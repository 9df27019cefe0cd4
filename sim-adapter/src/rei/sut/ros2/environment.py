# SPDX-License-Identifier: EPL-2.0
"""Where a run's ROS 2 traffic goes: a DDS domain of the run's own, on loopback only, whatever the stack's DDS.

Runs are kept apart by the ROS domain id, which every DDS vendor maps to its own UDP ports (the RTPS port mapping),
so a stack on Fast DDS, Cyclone DDS or any other implementation is isolated alike. Each run claims a free domain
of ``RUN_DOMAINS`` with a lock file per domain (``DomainLease``), held by the bridge for the run's lifetime: two
runs or a campaign's workers on one machine never share one. The stack gets ``ROS_DOMAIN_ID`` and ROS 2's own
localhost-only switches: ``ROS_LOCALHOST_ONLY=1`` (Humble) and ``ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST`` (Jazzy
and later); a stack on Cyclone DDS also gets REI's Cyclone configuration (``CYCLONEDDS_URI``: the loopback
interface with unicast discovery to 127.0.0.1). ``RMW_IMPLEMENTATION`` is the user's (ROS 2's default when unset).
"""

from __future__ import annotations

import errno
import fcntl
import os
import socket
from collections.abc import Mapping
from pathlib import Path
from types import TracebackType
from typing import Self
from xml.sax.saxutils import escape

from rei.private_dirs import UnsafeFolderError, private_dir, user_runtime_dir

#: Cyclone's port mapping allows 0..232.
MAX_DOMAIN = 232
#: The domains REI gives runs: ROS 2 recommends 0..101 on Linux (higher domains' ports reach into the kernel's
#: ephemeral range, 32768 and up); 0 is left to the machine's own ROS 2 (every node's default).
RUN_DOMAINS = range(1, 102)


#: Participants per domain reached by unicast discovery on loopback: Cyclone sends its announcements to the ports
#: of participant indices 0..this (default 9), and a stack of one process per node has more participants.
MAX_PARTICIPANT_INDEX = 49


def discovery_port(domain: int) -> int:
    """The RTPS unicast discovery port of participant 0 in ``domain`` (7400 + 250 d + 10), the same for every DDS
    vendor."""
    return 7400 + 250 * domain + 10


def lock_dir() -> Path:
    """The folder of the domain locks: ``ros2-domains`` in the user's private runtime folder, ``/tmp/rei-UID``
    (``rei.private_dirs``: named from the uid alone, so all of the user's processes share the locks, whatever their
    ``TMPDIR`` or ``XDG_RUNTIME_DIR``; created 0700, and refused when someone else could enter or redirect it)."""
    return private_dir(user_runtime_dir() / "ros2-domains")


class DomainUnavailableError(RuntimeError):
    pass


class DomainLease:
    """A ROS domain held by this process until ``release()`` (or the process's end: the kernel drops an exclusive
    ``flock`` with its last open descriptor, so a dead run's lock is free again at once, with no stale file to
    clean up)."""

    def __init__(self, domain: int, descriptor: int) -> None:
        self.domain = domain
        self._descriptor: int | None = descriptor

    @classmethod
    def claim(cls, domain: int | None = None, folder: Path | None = None) -> DomainLease:
        """The given domain, or else the first of ``RUN_DOMAINS`` that no other run holds and no DDS participant
        on this machine uses (participant 0's discovery port is free). ``folder`` (default ``lock_dir()``) is
        checked private like it."""
        folder = private_dir(folder) if folder is not None else lock_dir()
        if domain is not None:
            lease = cls._try(domain, folder)
            if lease is None:
                raise DomainUnavailableError(f"ROS domain {domain} is held by another run of REI on this machine "
                                             f"(lock {folder / f'domain-{domain}.lock'})")
            return lease
        for candidate in RUN_DOMAINS:
            lease = cls._try(candidate, folder)
            if lease is None:
                continue
            if _port_in_use(discovery_port(candidate)):  # a ROS 2 system outside REI is on this domain
                lease.release()
                continue
            return lease
        raise DomainUnavailableError(f"every ROS domain of {RUN_DOMAINS.start}..{RUN_DOMAINS.stop - 1} is in use "
                                     f"on this machine (locks in {folder})")

    @classmethod
    def _try(cls, domain: int, folder: Path) -> DomainLease | None:
        path = folder / f"domain-{domain}.lock"
        try:  # O_NOFOLLOW: a symbolic link in place of the lock file is refused, never followed to its target
            descriptor = os.open(path, os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW | os.O_CLOEXEC, 0o600)
        except OSError as error:
            if error.errno == errno.ELOOP:
                raise UnsafeFolderError(f"{path}: a symbolic link, not a lock file: REI does not follow it; "
                                        f"remove it") from error
            raise
        try:
            fcntl.flock(descriptor, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError as error:
            os.close(descriptor)
            if error.errno in (errno.EWOULDBLOCK, errno.EACCES):
                return None
            raise
        # who holds it, for a person looking: written over the start, never truncating, in a fixed width (Linux
        # pids have at most 7 digits) so that it replaces the previous holder's whole
        os.pwrite(descriptor, f"{os.getpid():<10}\n".encode(), 0)
        return cls(domain, descriptor)

    def release(self) -> None:
        if self._descriptor is not None:
            os.close(self._descriptor)  # drops the lock; the file stays for the next run
            self._descriptor = None

    def __enter__(self) -> Self:
        return self

    def __exit__(self, kind: type[BaseException] | None, error: BaseException | None,
                 trace: TracebackType | None) -> None:
        self.release()


def _port_in_use(port: int) -> bool:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        try:
            probe.bind(("127.0.0.1", port))
        except OSError:
            return True
    return False


def cyclone_config(trace: Path | None = None) -> str:
    """Cyclone DDS's XML configuration of a run: the loopback interface, unicast discovery to 127.0.0.1 (no
    multicast, which loopback does not carry) for participant indices up to MAX_PARTICIPANT_INDEX; ``trace`` (optional) a file for Cyclone's configuration trace, which
    shows the interface it chose."""
    tracing = (f"<Tracing><Verbosity>config</Verbosity><OutputFile>{escape(str(trace))}</OutputFile></Tracing>"
               if trace is not None else "")
    return ("<CycloneDDS><Domain><General><Interfaces><NetworkInterface name=\"lo\"/></Interfaces>"
            "<AllowMulticast>false</AllowMulticast></General><Discovery><ParticipantIndex>auto</ParticipantIndex>"
            f"<MaxAutoParticipantIndex>{MAX_PARTICIPANT_INDEX}</MaxAutoParticipantIndex>"
            f"<Peers><Peer address=\"127.0.0.1\"/></Peers></Discovery>{tracing}</Domain></CycloneDDS>")


def ros2_environment(domain: int, config: str, home: Path, base: Mapping[str, str] = os.environ) -> dict[str, str]:
    """The environment of the ROS 2 stack: the run's domain, loopback only, logs under ``home``.

    REI's own variables (the router and its credentials) are left out: the stack talks ROS, not WAMP. A
    ``CYCLONEDDS_URI`` of the user's is kept, REI's configuration after it (Cyclone merges them, the later one
    winning), so the loopback set-up holds; ``RMW_IMPLEMENTATION`` is left as the user set it. ``PATH`` has REI's
    Python environment first, as for any started SUT (docs/sut.md), also when the bridge was started by hand."""
    from rei.sut.external.process import search_path

    env = {key: value for key, value in base.items() if not key.startswith("REI_")}
    user_config = base.get("CYCLONEDDS_URI", "").strip()
    env.update({"PATH": search_path(base), "ROS_DOMAIN_ID": str(domain),
                "CYCLONEDDS_URI": f"{user_config},{config}" if user_config else config, "ROS_LOCALHOST_ONLY": "1",
                "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST", "ROS_HOME": str(home),
                "ROS_LOG_DIR": str(home / "log"), "PYTHONUNBUFFERED": "1"})
    return env

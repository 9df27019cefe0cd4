# SPDX-License-Identifier: EPL-2.0
"""A run on a node that shares nothing with the driver but Ray: its inputs go there as bytes, its folder comes back.

Driver side: ``inputs`` packs what a run reads besides REI itself (the generated case folder, the user's patterns
and utilities, a ``script:`` controller's file, the files an external SUT's command names) into bundles of file
bytes by relative path; the case's bundle is put in Ray's object store once per campaign and shared by its runs.
Node side: ``run_shipped`` unpacks them into a temporary folder of its own, runs the supervised worker there with
every path pointing into that folder, and hands the run folder back as a list of files, each a list of object
store chunks of at most ``CHUNK`` bytes (put by the node, fetched and written one chunk at a time by the driver:
no file is held whole in the driver's memory). Driver side again: ``receive`` writes them to a staging folder
beside the run's and swaps it in only once every chunk arrived, so a node lost in the middle leaves nothing half
written, and the run's ``task.json`` is the driver's task (what resuming compares).
"""

from __future__ import annotations

import contextlib
import json
import os
import shlex
import shutil
import tempfile
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path
from typing import Any

from rei.campaign.plan import TASK_FILE, RunTask, write_task

#: Bytes per object store chunk of a returned file: big enough for few round trips, small enough to bound memory.
CHUNK = 4 * 1024 * 1024
#: Files a bundle may not hold: a folder's files above this are refused with a clear error rather than shipped.
MAX_INPUT_BYTES = 512 * 1024 * 1024

Bundle = dict[str, bytes]


def folder_bundle(folder: Path, under: str = "") -> Bundle:
    """Every file below ``folder`` (symbolic links followed), by its posix path relative to it, prefixed ``under``."""
    files: Bundle = {}
    total = 0
    for path in sorted(folder.rglob("*")):
        if path.is_file():
            data = path.read_bytes()
            total += len(data)
            if total > MAX_INPUT_BYTES:
                raise ValueError(f"{folder} holds more than {MAX_INPUT_BYTES // 2**20} MiB: too big to ship to a node")
            files[under + path.relative_to(folder).as_posix()] = data
    return files


def inputs(task: RunTask) -> tuple[Bundle, dict[str, Any]]:
    """The bundle of a task's inputs other than its case folder, and the task's fields to rewrite on the node,
    relative to the folder the bundle is unpacked in (``rewrite`` makes them absolute there)."""
    files: Bundle = {}
    fields: dict[str, Any] = {}
    if task.patterns:
        patterns = Path(task.patterns)
        if patterns.is_dir():
            files.update(folder_bundle(patterns, "patterns/"))
            fields["patterns"] = "patterns"
        else:
            files["patterns/" + patterns.name] = patterns.read_bytes()
            fields["patterns"] = "patterns/" + patterns.name
    if task.utilities:
        utilities = Path(task.utilities)
        files["utilities/" + utilities.name] = utilities.read_bytes()
        fields["utilities"] = "utilities/" + utilities.name
    name, _, arg = task.controller.partition(":")
    if task.sut is None and name == "script" and arg and Path(arg).is_file():
        files["controller/" + Path(arg).name] = Path(arg).read_bytes()
        fields["controller"] = "controller/" + Path(arg).name  # script:<the node's inputs folder>/controller/NAME
    if task.sut is not None and task.sut.get("cwd"):
        # the command runs in the spec's folder: ship the files its words name there (``python3 my_nav.py``)
        cwd = Path(task.sut["cwd"])
        try:
            words = shlex.split(task.sut["command"])
        except ValueError:
            words = []
        for word in words:
            path = cwd / word
            if not Path(word).is_absolute() and path.is_file():
                files["sut/" + Path(os.path.normpath(word)).as_posix()] = path.read_bytes()
        fields["sut_cwd"] = "sut"
    return files, fields


def unpack(files: Bundle, folder: Path) -> None:
    root = folder.resolve()
    for name, data in files.items():
        target = (root / name).resolve()
        if not target.is_relative_to(root):  # a bundle names files below its folder only
            raise ValueError(f"bundle path {name!r} leaves its folder")
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(data)


def rewrite(task: RunTask, work: Path, fields: dict[str, Any], create: bool = True) -> RunTask:
    """The task as it runs on the node: its case, run folder and inputs in ``work``."""
    inputs_dir = work / "inputs"
    changes: dict[str, Any] = {"case_dir": str(work / "case"), "run_dir": str(work / "run")}
    for name in ("patterns", "utilities"):
        if name in fields:
            changes[name] = str(inputs_dir / fields[name])
    if "controller" in fields:
        changes["controller"] = f"script:{inputs_dir / fields['controller']}"
    if task.sut is not None and task.sut.get("cwd"):
        changes["sut"] = {**task.sut, "cwd": str(inputs_dir / fields.get("sut_cwd", "sut"))}
        if create:  # the command's folder, even when no file of it was shipped
            (inputs_dir / "sut").mkdir(parents=True, exist_ok=True)
    return replace(task, **changes)


#: This Ray worker process's warm monitor JVM (rei.run.jvm.JarServer), started by its first run and kept for the
#: next ones as the local backend keeps one for all its runs: a replay there costs ~0.1-0.3 s of CPU instead of a
#: JVM's start and rule build (~3-4 s). It ends with the Ray worker (its standard input closes).
_monitor: Any = None
#: The folder of a Ray worker's warm monitor JVM (its socket and log), named after the worker's pid: Ray ends a
#: job's workers without running their exit handlers, so the next worker on the node removes a dead one's.
_MONITOR_FOLDER = "rei-node-monitor-"


def _warm_monitor() -> dict[str, str]:
    """The environment that sends this worker's runs' replays to its warm monitor JVM ({} when none starts: each
    replay then starts a JVM of its own, as before)."""
    global _monitor
    from rei.campaign.worker import MONITOR_SERVER_ENV

    if _monitor is None or not _monitor.alive():
        import atexit

        from rei.run.jvm import JarServer, JarServerError
        from rei.toolchain import ToolchainError

        if _monitor is None:
            sweep_monitor_folders()
        else:
            _monitor.stop()
        folder = Path(tempfile.mkdtemp(prefix=f"{_MONITOR_FOLDER}{os.getpid()}-"))  # 0700: its socket runs commands
        server = JarServer("monitor", folder / "monitor-server.log", folder)
        try:
            server.start()
        except (JarServerError, ToolchainError, OSError):
            shutil.rmtree(folder, ignore_errors=True)
            return {}
        atexit.register(lambda: (server.stop(), shutil.rmtree(folder, ignore_errors=True)))
        _monitor = server
    return {MONITOR_SERVER_ENV: str(_monitor.socket)}


def sweep_monitor_folders(wait: float = 0.0) -> None:
    """Removes the warm monitor folders of this machine's Ray workers that are gone; ``wait``: seconds to give
    workers that are ending (a local Ray instance just shut down) to be gone."""
    import time

    deadline = time.monotonic() + wait
    for folder in Path(tempfile.gettempdir()).glob(f"{_MONITOR_FOLDER}*"):
        pid = folder.name[len(_MONITOR_FOLDER):].split("-")[0]
        while pid.isdigit():
            try:
                os.kill(int(pid), 0)
            except ProcessLookupError:
                shutil.rmtree(folder, ignore_errors=True)
                break
            except OSError:  # alive, someone else's
                break
            if time.monotonic() > deadline:
                break
            time.sleep(0.05)


def run_shipped(task: dict[str, Any], case: Bundle, extra: Bundle, fields: dict[str, Any], attempt: int,
                needs: tuple[Any, ...] = (False, False)) -> dict[str, Any]:
    """The Ray task: the run in a temporary folder of this node's, its files returned as object store chunks.
    First it asks whether this node can run it (rei.campaign.nodes.node_lacks; ``needs``: the runs' router and
    people, and the driver's REI build): one that cannot returns ``{"unfit": what it lacks, "node": its id}`` without running."""
    import ray

    from rei.campaign.nodes import node_lacks
    from rei.campaign.supervise import supervise, worker_command
    from rei.lifetime import die_with_parent

    lacks = node_lacks(*needs)
    if lacks:
        return {"unfit": lacks, "node": ray.get_runtime_context().get_node_id()}
    work = Path(tempfile.mkdtemp(prefix="rei-run-"))
    try:
        unpack(case, work / "case")
        unpack(extra, work / "inputs")
        local = rewrite(RunTask.from_dict(task), work, fields)
        run_dir = Path(local.run_dir)
        # the worker process dies with this Ray worker (a node lost, a task cancelled by force), not after it
        env = _warm_monitor() if local.mode == "replay" else {}  # pipeline runs' monitors are live
        outcome = supervise(local, command=die_with_parent(worker_command(run_dir)), env=env)
        files = []
        for path in sorted(run_dir.rglob("*")):
            if not path.is_file() or path == run_dir / TASK_FILE:  # the driver writes its own task.json
                continue
            chunks = []
            with open(path, "rb") as f:
                while chunk := f.read(CHUNK):
                    chunks.append(ray.put(chunk))
            files.append((path.relative_to(run_dir).as_posix(), chunks))
        return {"outcome": {**outcome.to_dict(), "attempt": attempt}, "files": files, "work": str(work)}
    finally:
        shutil.rmtree(work, ignore_errors=True)


def receive(task: RunTask, files: list[tuple[str, list[Any]]], get: Callable[[Any], bytes],
            work: str | None = None, fields: dict[str, Any] | None = None) -> int:
    """Writes a shipped run's files into ``task.run_dir`` (replacing what was there) and its ``task.json``; the
    bytes received. ``get`` fetches one chunk (``ray.get``); one that fails leaves the run folder as it was.
    ``work``: the node's folder the run ran in (``fields``: as ``inputs`` gave them), whose paths
    ``summary.json`` names as the driver's."""
    run_dir = Path(task.run_dir)
    staging = run_dir.with_name(f".{run_dir.name}.incoming")
    shutil.rmtree(staging, ignore_errors=True)
    received = 0
    try:
        staging.mkdir(parents=True)
        for name, chunks in files:
            target = (staging / name).resolve()
            if not target.is_relative_to(staging.resolve()):
                raise ValueError(f"run file {name!r} leaves its folder")
            target.parent.mkdir(parents=True, exist_ok=True)
            with open(target, "wb") as out:
                for ref in chunks:
                    data = get(ref)
                    out.write(data)
                    received += len(data)
        if work is not None and (staging / "summary.json").is_file():
            _driver_paths(staging / "summary.json", task, work, fields or {})
        write_task(task, staging)
        if run_dir.exists():
            shutil.rmtree(run_dir)
        os.replace(staging, run_dir)
    finally:
        with contextlib.suppress(OSError):
            shutil.rmtree(staging, ignore_errors=True)
    return received


def _driver_paths(path: Path, task: RunTask, work: str, fields: dict[str, Any]) -> None:
    """The node's paths in a run's JSON file (summary.json says which patterns and utilities judged the run) made
    the ones a local run writes: the run's, the case's and the user's files on the driver."""
    node = rewrite(task, Path(work), fields, create=False)
    pairs = [(node.run_dir, task.run_dir), (node.case_dir, task.case_dir)]
    pairs += [(getattr(node, name), getattr(task, name)) for name in ("patterns", "utilities") if getattr(task, name)]
    text = path.read_text(encoding="utf-8")
    for theirs, ours in sorted(pairs, key=lambda pair: -len(pair[0])):  # the longest first: one may hold another
        text = text.replace(json.dumps(theirs)[1:-1], json.dumps(ours)[1:-1])
    path.write_text(text, encoding="utf-8")

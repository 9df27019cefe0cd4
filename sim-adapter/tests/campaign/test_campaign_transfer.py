# SPDX-License-Identifier: EPL-2.0
"""rei.campaign.transfer without Ray: what a run's inputs bundle holds and where the node's task points, that a
bundle cannot write outside its folder, and that a run folder is swapped in only once every chunk arrived."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rei.campaign.plan import RunTask
from rei.campaign.transfer import CHUNK, folder_bundle, inputs, receive, rewrite, unpack


def _task(tmp_path: Path, **changes: object) -> RunTask:
    fields: dict[str, object] = {
        "key": "g__c__v__r0", "group": "g", "case": "c", "variant": "v", "repetition": 0, "seed": 1, "humans": False,
        "fault": None, "controller": "nav", "mode": "replay", "timeout": 60.0, "report": False,
        "case_dir": str(tmp_path / "out" / "cases" / "c"), "run_dir": str(tmp_path / "out" / "runs" / "g__c__v__r0")}
    return RunTask(**{**fields, **changes})  # type: ignore[arg-type]


def test_the_inputs_bundle_holds_the_users_files_and_the_node_task_points_into_its_folder(tmp_path: Path) -> None:
    (tmp_path / "mine" / "sub").mkdir(parents=True)
    (tmp_path / "mine" / "a.vepl").write_text("A", encoding="utf-8")
    (tmp_path / "mine" / "sub" / "b.vepl").write_text("B", encoding="utf-8")
    (tmp_path / "u.yaml").write_text("X: 1\n", encoding="utf-8")
    (tmp_path / "steps.txt").write_text("1.0 0.1 0.0\n", encoding="utf-8")
    task = _task(tmp_path, patterns=str(tmp_path / "mine"), utilities=str(tmp_path / "u.yaml"),
                 controller=f"script:{tmp_path / 'steps.txt'}")
    files, fields = inputs(task)
    assert files == {"patterns/a.vepl": b"A", "patterns/sub/b.vepl": b"B", "utilities/u.yaml": b"X: 1\n",
                     "controller/steps.txt": b"1.0 0.1 0.0\n"}
    work = tmp_path / "node"
    unpack(files, work / "inputs")
    node = rewrite(task, work, fields)
    assert (node.case_dir, node.run_dir) == (str(work / "case"), str(work / "run"))
    assert Path(node.patterns or "", "sub", "b.vepl").read_text(encoding="utf-8") == "B"
    assert Path(node.utilities or "").read_text(encoding="utf-8") == "X: 1\n"
    assert node.controller == f"script:{work / 'inputs' / 'controller' / 'steps.txt'}"
    assert (node.key, node.seed, node.fault) == (task.key, task.seed, task.fault)


def test_an_external_suts_files_named_by_its_command_travel_and_it_runs_in_their_folder(tmp_path: Path) -> None:
    (tmp_path / "my_nav.py").write_text("print(1)\n", encoding="utf-8")
    sut = {"command": "python3 my_nav.py --fast missing.py", "clock": "lockstep", "deadline": 1.0, "map": False,
           "join_timeout": 10.0, "cwd": str(tmp_path)}
    task = _task(tmp_path, sut=sut)
    files, fields = inputs(task)
    assert files == {"sut/my_nav.py": b"print(1)\n"}  # a word that names no file there is left alone
    node = rewrite(task, tmp_path / "node", fields)
    assert node.sut == {**sut, "cwd": str(tmp_path / "node" / "inputs" / "sut")}
    assert node.controller == "nav"


def test_a_bundle_cannot_write_outside_its_folder(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="leaves its folder"):
        unpack({"../escaped": b"x"}, tmp_path / "in")
    assert not (tmp_path / "escaped").exists()


def test_a_case_folder_is_bundled_whole(tmp_path: Path) -> None:
    (tmp_path / "case" / "maps").mkdir(parents=True)
    (tmp_path / "case" / "world.json").write_bytes(b"{}")
    (tmp_path / "case" / "maps" / "m.pgm").write_bytes(bytes(range(256)))
    assert folder_bundle(tmp_path / "case") == {"maps/m.pgm": bytes(range(256)), "world.json": b"{}"}


def test_a_run_folder_is_replaced_only_once_every_chunk_arrived(tmp_path: Path) -> None:
    task = _task(tmp_path)
    run = Path(task.run_dir)
    run.mkdir(parents=True)
    (run / "old.txt").write_text("earlier try", encoding="utf-8")
    big = bytes(range(256)) * (CHUNK // 256) + b"tail"  # two chunks
    store = {1: big[:CHUNK], 2: big[CHUNK:], 3: b"{}"}

    def lost(ref: int) -> bytes:
        if ref == 2:
            raise ConnectionError("the node is gone")
        return store[ref]

    with pytest.raises(ConnectionError):
        receive(task, [("streams/state.msgpack", [1, 2]), ("summary.json", [3])], lost)
    assert sorted(p.name for p in run.iterdir()) == ["old.txt"]  # as it was
    assert not list(run.parent.glob(".*"))  # no staging folder left

    received = receive(task, [("streams/state.msgpack", [1, 2]), ("summary.json", [3])], store.__getitem__)
    assert received == len(big) + 2
    assert sorted(p.relative_to(run).as_posix() for p in run.rglob("*") if p.is_file()) == [
        "streams/state.msgpack", "summary.json", "task.json"]
    assert (run / "streams" / "state.msgpack").read_bytes() == big
    assert json.loads((run / "task.json").read_text(encoding="utf-8")) == task.to_dict()  # the driver's task


def test_the_summary_names_the_drivers_paths_not_the_nodes(tmp_path: Path) -> None:
    (tmp_path / "u.yaml").write_text("X: 1\n", encoding="utf-8")
    task = _task(tmp_path, utilities=str(tmp_path / "u.yaml"))
    _, fields = inputs(task)
    work = "/tmp/rei-run-abc"
    summary = json.dumps({"utilities": f"Table 3 + {work}/run/patterns + {work}/inputs/utilities/u.yaml"})
    receive(task, [("summary.json", [1])], {1: summary.encode()}.__getitem__, work, fields)
    written = json.loads((Path(task.run_dir) / "summary.json").read_text(encoding="utf-8"))
    assert written == {"utilities": f"Table 3 + {task.run_dir}/patterns + {tmp_path / 'u.yaml'}"}

# SPDX-License-Identifier: EPL-2.0
"""The live view in headless Chromium, fed synthetic messages through the real router: it keeps up with a
stream faster than real time, shows gaps, stalls and the run's end, names floors on hover, and draws 200 moving
objects within a frame's budget."""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from playwright.sync_api import Browser
from view_helpers import SHOTS, ViewPage, state_message, synthetic_world, write_case

from rei.view import ViewServer, view_config
from rei.wamp import Router, Topics, WampClient

View = tuple[ViewPage, WampClient, Topics]


@pytest.fixture
def view(browser: Browser, router: Router, tmp_path: Path, request: pytest.FixtureRequest) -> Iterator[View]:
    humans = getattr(request, "param", 1)
    run_id = f"view-{request.node.name[:40]}".replace("[", "-").replace("]", "")
    case = write_case(tmp_path / "case", synthetic_world(16 if humans > 1 else 6, 10 if humans > 1 else 4, humans))
    with ViewServer(view_config(router.ws_url, run_id, case)) as server, WampClient(router.rs_url) as client:
        page = ViewPage(browser, server.url)
        try:
            yield page, client, Topics(run_id)
            assert page.errors == []
        finally:
            page.close()


def test_it_keeps_up_with_400_states_a_second_dropping_frames_never_lagging(view: View) -> None:
    page, client, topics = view
    published: dict[int, float] = {}
    count = 2000  # 5 s at 400 messages/s: a 20 Hz simulation at 20x real time

    def publish() -> None:
        start = time.monotonic()
        for seq in range(count):
            delay = start + seq / 400 - time.monotonic()
            if delay > 0:
                time.sleep(delay)
            published[seq] = time.time() * 1000
            client.publish(topics.state, state_message(seq, seq * 0.05, (0.5 + 5 * seq / count, 2.0)))

    publisher = threading.Thread(target=publish)
    publisher.start()
    samples = []
    while publisher.is_alive():
        state = page.state()
        if state["robot"] is not None:
            samples.append((state["robot"]["seq"], state["drawnAtMs"]))
        time.sleep(0.1)
    publisher.join()
    page.wait_for(f"state.robot !== null && state.robot.seq === {count - 1}")
    final = page.state()
    lags = [drawn - published[seq] for seq, drawn in samples]
    print(f"lag drawn - published: max {max(lags):.0f} ms, mean {sum(lags) / len(lags):.0f} ms over {len(lags)} samples;"
          f" dropped {final['dropped']} of {final['received']['state']}; frames {page.page.evaluate('window.reiView.frames()')}")
    assert len(samples) > 20
    assert max(lags) < 1000
    assert final["drawnAtMs"] - published[count - 1] < 1000
    assert final["received"]["state"] == count and final["gaps"] == []
    assert final["dropped"] > count / 3  # at most one state per screen refresh is drawn
    assert final["robot"]["pose"][0] == pytest.approx(0.5 + 5 * (count - 1) / count)


def test_a_gap_a_stall_and_the_end_are_shown(view: View) -> None:
    page, client, topics = view
    for seq in [*range(50), *range(60, 100)]:
        client.publish(topics.state, state_message(seq, seq * 0.05, (1.0, 1.0)))
    client.flush()
    page.wait_for("state.gaps.length === 1")
    (gap,) = page.state()["gaps"]
    assert (gap["topic"], gap["from"], gap["to"]) == ("state", 50, 59)
    banner = page.page.locator("#banners .gap")
    assert "10 state messages lost (seq 50–59)" in banner.inner_text()
    page.wait_for("state.condition === 'stalled'")  # nothing for 1.5 s, the run not ended
    assert "No state message" in page.page.locator("#banners .stalled").inner_text()
    client.publish(topics.mission, {"seq": 0, "t": 5.0, "event": "END", "task_index": -1, "goal": None})
    client.flush()
    page.wait_for("state.condition === 'ended'")
    assert "Run ended at t = 5.0 s" in page.page.locator("#banners .ended").inner_text()
    assert page.page.locator("#status").inner_text() == "run ended"


def test_fault_windows_are_shaded_on_the_utility_chart(view: View) -> None:
    """A fault's window edges arrive as mission events (rei.view.view_config names them from the contract's fault
    kinds); the chart shades each window, an open one up to the latest time, and leaves the rest white."""
    page, client, topics = view
    edges = [(2.0, "FAULT_LASER_BLACKOUT_BEGIN"), (4.0, "FAULT_LASER_BLACKOUT_END"),
             (6.0, "FAULT_COMMANDS_LOSS_BEGIN")]
    for seq, (t, event) in enumerate(edges):
        client.publish(topics.mission, {"seq": seq, "t": t, "event": event, "task_index": -1, "goal": None,
                                        "reason": event.lower()})
    for seq in range(201):
        client.publish(topics.state, state_message(seq, seq * 0.05, (1.0, 1.0)))
    client.flush()
    page.wait_for("state.robot !== null && state.robot.seq === 200 && state.faults.length === 2")
    assert page.state()["faults"] == [{"fault": "laser blackout", "begin": 2.0, "end": 4.0},
                                      {"fault": "commands loss", "begin": 6.0, "end": None}]
    # the run's end redraws the chart up to the latest state (10 s), the loss still open
    client.publish(topics.mission, {"seq": len(edges), "t": 10.0, "event": "END", "task_index": -1, "goal": None})
    client.flush()
    page.wait_for("state.condition === 'ended'")
    page.page.wait_for_timeout(300)  # a frame or two after the end
    # the canvas's pixels half-way up at t = 1 (white), 3 (shaded), 5 (white) and 8 s (shaded, still open); the
    # chart spans 0..10 s over its plot (PAD left 38, right 8 CSS pixels, rei viewer/src/draw/chart.ts)
    colours = page.page.evaluate("""() => {
      const canvas = document.getElementById("utility");
      const ratio = canvas.width / canvas.clientWidth;
      const x = (t) => Math.round((38 + (t / 10) * (canvas.clientWidth - 46)) * ratio);
      const y = Math.round(canvas.height * 0.4);
      return [1, 3, 5, 8].map((t) => Array.from(canvas.getContext("2d").getImageData(x(t), y, 1, 1).data));
    }""")
    white, shaded = [255, 255, 255, 255], [253, 239, 215, 255]  # FAULT_FILL, rgba(245, 166, 35, 0.18), over white
    assert [c == white for c in colours] == [True, False, True, False], colours
    assert all(abs(a - b) <= 2 for c in (colours[1], colours[3]) for a, b in zip(c, shaded, strict=True)), colours


def test_floors_and_furniture_are_named_on_hover(view: View) -> None:
    page, client, topics = view
    client.publish(topics.state, state_message(0, 0.0, (0.5, 0.5)))
    client.flush()
    page.wait_for("state.robot !== null")
    box = page.page.locator("#map").bounding_box()
    assert box is not None
    tf = page.state()["transform"]

    def hover(x: float, y: float) -> str:
        page.page.mouse.move(box["x"] + tf["ox"] + x * tf["scale"], box["y"] + tf["oy"] - y * tf["scale"])
        return page.page.locator("#tooltip").inner_text()

    assert hover(5.5, 3.5).startswith("floor F_5_3")
    assert hover(3.5, 1.5).startswith("table1 (Table)")
    assert hover(1.5, 2.5).startswith("floor F_1_2")


@pytest.mark.parametrize("view", [200], indirect=True)
def test_200_moving_objects_draw_within_a_frame(view: View) -> None:
    page, client, topics = view
    names = [f"h{k}" for k in range(200)]

    def humans(t: float) -> list[tuple[str, float, float]]:
        return [(name, 8 + (1 + k % 7) * math.cos(t + k), 5 + (1 + k % 4) * math.sin(t + k))
                for k, name in enumerate(names)]

    rate, seconds = 60, 6.0
    start = time.monotonic()
    measuring = False
    for seq in range(int(rate * seconds)):
        delay = start + seq / rate - time.monotonic()
        if delay > 0:
            time.sleep(delay)
        t = seq / rate
        client.publish(topics.state, state_message(seq, t, (2 + t, 2.0), humans(t)))
        if not measuring and t >= 1.5:  # warm-up: JIT, first layout
            page.page.evaluate("window.reiView.resetFrames()")
            measuring = True
    client.flush()
    frames = page.page.evaluate("window.reiView.frames()")
    state = page.state()
    print(f"200 moving objects: {frames['frames']} frames, mean {frames['meanMs']:.2f} ms, "
          f"p95 {frames['p95Ms']:.2f} ms, max {frames['maxMs']:.2f} ms, frame interval {frames['intervalMs']:.1f} ms")
    SHOTS.mkdir(parents=True, exist_ok=True)
    page.page.screenshot(path=str(SHOTS / "200-objects.png"))
    assert state["movers"] == 200
    assert frames["frames"] >= 100  # drawn at screen rate, not once
    assert frames["p95Ms"] < 16.0 and frames["meanMs"] < 16.0

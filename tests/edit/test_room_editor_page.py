# SPDX-License-Identifier: EPL-2.0
"""The room editor in Debian's chromium: what a test engineer does with the mouse ends up in the `.rei` file, and
only that; validation shows on the diagram's elements; a change of the file on disk is noticed.

Each test opens a copy of a file in a real edit engine behind a real server (tests/edit/conftest.py) and drives
the page with Playwright's mouse and keyboard, as a user would.
"""

from __future__ import annotations

import difflib
import re
from pathlib import Path

from edit_helpers import SHOTS, Editor, write_as_another_program
from page_helpers import click_floor, drag, element, open_page, settled
from playwright.sync_api import Page

REPO = Path(__file__).resolve().parents[2]


def test_drag_add_goal_draw_path_and_save_change_only_those_lines(open_editor, page: Page, run_cli) -> None:
    editor: Editor = open_editor("examples/simple_navigation.rei")
    before = editor.case.read_text(encoding="utf-8")
    open_page(page, editor)
    page.screenshot(path=str(SHOTS / "opened.png"))
    version = editor.session.status()["version"]

    drag(page, element(page, "object", "table1"), element(page, "floor", "F_3_3"))
    version = settled(editor, page, version)
    page.locator("#dirty").wait_for(state="visible")

    page.click("#add-goal")
    click_floor(page, "F_2_3")
    version = settled(editor, page, version)
    page.locator('[data-kind="goal"][data-index="2"]').wait_for()

    element(page, "human", "walker").click()
    page.click("#draw-path")
    for floor in ("F_0_2", "F_2_2", "F_4_3"):
        click_floor(page, floor)
    page.click("#finish-path")
    version = settled(editor, page, version)

    page.click("#save")
    page.locator("#dirty").wait_for(state="hidden")
    page.screenshot(path=str(SHOTS / "edited.png"))
    after = editor.case.read_text(encoding="utf-8")
    assert run_cli("validate", editor.case).returncode == 0

    changed = [line for line in difflib.ndiff(before.splitlines(), after.splitlines()) if line[:1] in "+-"]
    removed = [line[2:].strip() for line in changed if line.startswith("-")]
    added = [line[2:].strip() for line in changed if line.startswith("+")]
    assert removed == ["object table1 : Table on F_2_1",
                       "human walker trajectory [F_1_2 @ 0s, F_3_2 @ 6s, F_4_2 @ 9s] loop"], changed
    assert added[0] == "object table1 : Table on F_3_3", changed
    assert re.fullmatch(r"human walker trajectory \[F_0_2 @ 0s, F_2_2 @ \d+s, F_4_3 @ \d+s\] loop", added[1]), changed
    assert added[2:] == ["goto F_2_3"], changed
    assert after.index("goto F_2_3") > after.index("goto F_5_3"), "the new goal is not the last"


def test_two_objects_on_one_floor_show_the_validators_message_on_both(open_editor, page: Page) -> None:
    editor: Editor = open_editor("examples/simple_navigation.rei")
    open_page(page, editor)
    version = editor.session.status()["version"]
    page.click('[data-type="Box"]')
    click_floor(page, "F_2_1")  # table1's floor
    settled(editor, page, version)
    issues = page.locator("#issues")
    issues.get_by_text("is already taken by 'table1'").wait_for()
    for name in ("table1", "box1"):
        assert "has-issue" in (element(page, "object", name).get_attribute("class") or "")
        label = page.locator(f'.issue-label[data-for="{name}"]')
        label.wait_for(state="visible")
        assert "already taken" in label.inner_text()
    page.screenshot(path=str(SHOTS / "issue.png"))
    assert editor.session.dirty, "the page saved without being asked"


def test_a_moving_object_from_the_palette_is_one_new_line(open_editor, page: Page, run_cli) -> None:
    editor: Editor = open_editor("examples/simple_navigation.rei")
    before = editor.case.read_text(encoding="utf-8")
    open_page(page, editor)
    version = editor.session.status()["version"]
    page.click('[data-type="Cart"]')
    for floor in ("F_1_1", "F_3_1", "F_3_3"):
        click_floor(page, floor)
    page.click("#finish-path")
    settled(editor, page, version)
    element(page, "dynamic", "cart1").wait_for()
    page.click("#save")
    page.locator("#dirty").wait_for(state="hidden")

    after = editor.case.read_text(encoding="utf-8")
    changed = [line for line in difflib.ndiff(before.splitlines(), after.splitlines()) if line[:1] in "+-"]
    assert len(changed) == 1 and re.fullmatch(
        r"\+     dynamic cart1 : Cart trajectory \[F_1_1 @ 0s, F_3_1 @ \d+s, F_3_3 @ \d+s\]", changed[0]), changed
    assert run_cli("validate", editor.case).returncode == 0


def test_rotate_delete_reorder_goals_and_undo_redo(open_editor, page: Page) -> None:
    editor: Editor = open_editor("examples/simple_navigation.rei")
    before = editor.case.read_text(encoding="utf-8")
    open_page(page, editor)
    version = editor.session.status()["version"]
    element(page, "object", "table1").click()
    page.click("#rotate-left")
    version = settled(editor, page, version)
    assert re.search(r"object table1 : Table on F_2_1 yaw -?90\b", editor.session.text)
    element(page, "object", "shelf1").click()
    page.keyboard.press("Delete")
    version = settled(editor, page, version)
    assert "shelf1" not in editor.session.text
    page.locator('#goals li[data-index="1"] .up').click()
    version = settled(editor, page, version)
    goals = re.findall(r"goto (\w+)", editor.session.text)
    assert goals == ["F_5_3", "F_4_0"], goals

    for _ in range(3):
        page.keyboard.press("Control+z")
        version = settled(editor, page, version)
    assert editor.session.text == before and not editor.session.dirty
    page.keyboard.press("Control+Shift+z")
    version = settled(editor, page, version)
    page.click("#redo")
    settled(editor, page, version)
    assert "shelf1" not in editor.session.text and "yaw" in editor.session.text
    assert re.findall(r"goto (\w+)", editor.session.text) == ["F_4_0", "F_5_3"], "redo went past its step"


def test_a_file_changed_on_disk_is_noticed(open_editor, page: Page) -> None:
    editor: Editor = open_editor("examples/simple_navigation.rei")
    open_page(page, editor)
    text = editor.case.read_text(encoding="utf-8")
    # No unsaved edits: the editor follows the file and says so.
    write_as_another_program(editor.case, text.replace("shelf1 : Shelf on F_0_3", "shelf1 : Shelf on F_1_3"))
    page.locator("#toast").get_by_text("changed on disk").wait_for()
    page.wait_for_function("""() => {
        const shelf = document.querySelector('[data-kind="object"][data-name="shelf1"]');
        return shelf !== null && shelf.getAttribute("data-floor") === "F_1_3";
    }""")
    # Unsaved edits: the editor asks, and keeps both versions until the user chooses.
    version = editor.session.status()["version"]
    drag(page, element(page, "object", "table1"), element(page, "floor", "F_3_3"))
    settled(editor, page, version)
    theirs = text.replace("close 0.25", "close 0.5")
    write_as_another_program(editor.case, theirs)
    banner = page.locator("#disk-banner")
    banner.wait_for(state="visible")
    assert "changed on disk" in banner.inner_text()
    page.click("#save")
    page.locator("#toast").get_by_text("changed on disk").wait_for()
    assert editor.case.read_text(encoding="utf-8") == theirs
    page.click("#reload")
    banner.wait_for(state="hidden")
    page.locator("#dirty").wait_for(state="hidden")
    assert editor.session.text == theirs


def test_graph_rooms_gain_and_lose_floors_and_walls(open_editor, page: Page, run_cli, tmp_path: Path) -> None:
    editor: Editor = open_editor("tests/edit/rooms/corridor.rei")
    open_page(page, editor)
    floors = page.locator('[data-kind="floor"]')
    assert floors.count() == 3
    version = editor.session.status()["version"]
    ghost = page.locator('[data-kind="ghost"]').first
    ghost.click()
    version = settled(editor, page, version)
    page.wait_for_function("document.querySelectorAll('[data-kind=\"floor\"]').length === 4")
    element(page, "floor", "A").click(position={"x": 4, "y": 4})  # a corner: the robot stands in the middle
    page.locator("#wall-bottom").click()  # only free sides get a strip: the new floor may be on top
    version = settled(editor, page, version)
    element(page, "wall", "W_A_bottom").wait_for()
    page.click("#save")
    page.locator("#dirty").wait_for(state="hidden")
    assert run_cli("validate", editor.case).returncode == 0
    text = editor.case.read_text(encoding="utf-8")
    added = re.search(r"floor (\w+) (?:top|right|bottom|left) A", text)
    assert added is not None and "floor A right B bottom W_A_bottom" in text and "wall W_A_bottom" in text, text
    assert "// the corridor's comment stays" in text

    element(page, "wall", "W_A_bottom").click()
    page.keyboard.press("Delete")
    version = settled(editor, page, version)
    element(page, "wall", "W_A_bottom").wait_for(state="detached")
    element(page, "floor", added.group(1)).click(position={"x": 4, "y": 4})
    page.keyboard.press("Delete")
    settled(editor, page, version)
    page.click("#save")
    page.locator("#dirty").wait_for(state="hidden")
    assert editor.case.read_text(encoding="utf-8") == (REPO / "tests/edit/rooms/corridor.rei").read_text(encoding="utf-8")


def test_generated_rooms_and_the_examples_open(open_editor, page: Page, run_cli, tmp_path: Path) -> None:
    generated = tmp_path / "generated"
    assert run_cli("gen-rooms", "--size", "small", "--count", "1", "--seed", "3", "-o", generated,
                   "--no-check").returncode == 0
    cases = [*sorted(generated.glob("*.rei")), *sorted(Path("examples").glob("*.rei"))]
    for case in cases:
        editor: Editor = open_editor(case.resolve(), copy=False)  # in place: own_types imports a neighbour
        open_page(page, editor)
        diagram = editor.session.state()["diagram"]
        assert page.locator('[data-kind="floor"]').count() == len(diagram["room"]["floors"]), case
        assert page.locator('[data-kind="object"]').count() == len(diagram["objects"]), case
        assert page.locator('[data-kind="goal"]').count() == len(diagram["mission"]["goals"]), case

# SPDX-License-Identifier: EPL-2.0
"""People who see the robot in the room editor (issue #38, item 3: "draw a route, place a crowd area"), in Debian's
chromium: a routed person's route, a crowd's areas and a group's route are drawn on the room; a route is drawn,
a stop removed and a wait set with the mouse; a crowd is placed by dragging a rectangle of floors and clicking
floors, then its area moved; the saved `.rei` text changes only those lines and `rei validate` accepts it.

Each test opens a copy of an example in a real edit engine behind a real server (tests/edit/conftest.py).
"""

from __future__ import annotations

import difflib
import re

from edit_helpers import SHOTS, Editor
from page_helpers import centre, click_floor, element, open_page, settled
from playwright.sync_api import Page


def drag_floors(page: Page, first: str, last: str) -> None:
    """A rectangle dragged with the mouse from one floor's centre to another's."""
    (x0, y0), (x1, y1) = centre(element(page, "floor", first)), centre(element(page, "floor", last))
    page.mouse.move(x0, y0)
    page.mouse.down()
    page.mouse.move((x0 + x1) / 2, (y0 + y1) / 2, steps=5)
    page.mouse.move(x1, y1, steps=5)
    page.mouse.up()


def changed_lines(before: str, after: str) -> tuple[list[str], list[str]]:
    changed = [line for line in difflib.ndiff(before.splitlines(), after.splitlines()) if line[:1] in "+-"]
    return ([line[2:].strip() for line in changed if line.startswith("-")],
            [line[2:].strip() for line in changed if line.startswith("+")])


def test_draw_a_route_place_a_crowd_move_its_area_and_save(open_editor, page: Page, run_cli) -> None:
    editor: Editor = open_editor("examples/people/reactive_crossing.rei")
    before = editor.case.read_text(encoding="utf-8")
    open_page(page, editor)
    version = editor.session.status()["version"]

    # the routes as written: two stops each, a wait on the second
    ann = element(page, "human", "ann")
    assert ann.locator(".stop").count() == 2
    assert page.locator('.labels .wait[data-stop="1"]').first.text_content() == "wait 2 s"

    # Draw route: four floors clicked, the third removed, a wait set on the second, Finish
    ann.locator(".stop").first.click()
    page.click("#draw-route")
    for floor in ("F_2_3", "F_2_0", "F_6_0", "F_4_0"):
        click_floor(page, floor)
    assert page.locator("#stops li[data-stop]").count() == 4
    page.locator('#stops li[data-stop="2"] .remove-stop').click()
    page.locator('#stops li[data-stop="1"] .wait').fill("4")
    page.keyboard.press("Tab")  # the field's change commits it, as a user leaving it
    assert page.locator("#stops .floor").all_inner_texts() == ["F_2_3", "F_2_0", "F_4_0"]
    page.click("#finish-path")
    version = settled(editor, page, version)
    assert re.search(r"human ann route \[F_2_3, F_2_0 wait 4(\.0)?s, F_4_0\] speed 1\.1 loop avoids\n",
                     editor.session.text), editor.session.text
    assert element(page, "human", "ann").locator(".stop").count() == 3

    # a crowd from the palette: a rectangle of floors for its from area, two clicked floors for its to area
    page.click("#new-crowd")
    drag_floors(page, "F_6_1", "F_7_2")
    page.keyboard.press("Enter")  # no to area yet: the page says so and sends nothing
    page.locator("#toast").get_by_text("Choose the crowd's to area").wait_for()
    page.click("#crowd-to")
    click_floor(page, "F_0_2")
    click_floor(page, "F_0_3")
    page.locator("#crowd-count").fill("3")
    page.keyboard.press("Tab")
    page.locator("#crowd-rate").fill("0.5")
    page.keyboard.press("Tab")
    assert page.locator(".area-floors.from").inner_text() == "F_6_1, F_7_1, F_6_2, F_7_2"
    page.keyboard.press("Enter")
    version = settled(editor, page, version)
    assert "    crowd crowd1 3 from [F_6_1, F_7_1, F_6_2, F_7_2] to [F_0_2, F_0_3] rate 0.5\n" in editor.session.text
    crowd = element(page, "crowd", "crowd1")
    assert crowd.locator(".area.from rect").count() == 4 and crowd.locator(".area.to rect").count() == 2
    page.screenshot(path=str(SHOTS / "people.png"))

    # its to area moved: selected, Change areas, To, a rectangle elsewhere
    crowd.locator('.area.to rect[data-floor="F_0_2"]').click()
    page.click("#edit-areas")
    page.click("#crowd-to")
    drag_floors(page, "F_3_2", "F_4_2")
    page.click("#finish-path")
    version = settled(editor, page, version)
    assert "to [F_3_2, F_4_2] rate 0.5" in editor.session.text

    # one undo step per gesture, as every edit
    page.keyboard.press("Control+z")
    version = settled(editor, page, version)
    assert "to [F_0_2, F_0_3] rate 0.5" in editor.session.text
    page.keyboard.press("Control+Shift+z")
    version = settled(editor, page, version)
    assert "to [F_3_2, F_4_2] rate 0.5" in editor.session.text

    page.click("#save")
    page.locator("#dirty").wait_for(state="hidden")
    after = editor.case.read_text(encoding="utf-8")
    result = run_cli("validate", editor.case)
    assert result.returncode == 0, result.stdout + result.stderr
    removed, added = changed_lines(before, after)
    assert removed == ["human ann route [F_3_3, F_3_0 wait 2s] speed 1.1 loop avoids"], (removed, added)
    assert len(added) == 2 and added[1] == "crowd crowd1 3 from [F_6_1, F_7_1, F_6_2, F_7_2] to [F_3_2, F_4_2] rate 0.5"


def test_crowds_and_groups_are_drawn_and_a_crowd_is_resized_in_place(open_editor, page: Page) -> None:
    editor: Editor = open_editor("examples/people/crowds.rei")
    before = editor.case.read_text(encoding="utf-8")
    open_page(page, editor)
    version = editor.session.status()["version"]

    shoppers = element(page, "crowd", "shoppers")
    assert shoppers.locator(".area.from rect").count() == 8
    assert shoppers.locator(".area.to rect").count() == 8
    assert shoppers.locator(".crowd-arrow").count() == 2  # the line and its head
    family = element(page, "group", "family")
    assert family.locator(".stop").count() == 2
    assert "family ×3" in (page.locator(".labels").first.text_content() or "")
    page.screenshot(path=str(SHOTS / "crowds.png"))  # docs/images/room-editor-people.png comes from here

    shoppers.locator('.area.from rect[data-floor="F_0_2"]').click()
    page.locator("#crowd-count").fill("10")
    page.keyboard.press("Tab")
    settled(editor, page, version)
    removed, added = changed_lines(before, editor.session.text)
    # the crowd's three lines stay three lines: only its count changed
    assert removed == ["crowd shoppers 12 from [F_0_2, F_0_3, F_0_4, F_0_5, F_1_2, F_1_3, F_1_4, F_1_5]"]
    assert added == ["crowd shoppers 10 from [F_0_2, F_0_3, F_0_4, F_0_5, F_1_2, F_1_3, F_1_4, F_1_5]"]

    family.locator(".stop").first.click()
    page.locator("#selection").get_by_text("changed in the text").wait_for()

    # a crowd begun and dropped with Escape leaves the text as it was
    text = editor.session.text
    page.click("#new-crowd")
    drag_floors(page, "F_6_6", "F_7_7")
    page.keyboard.press("Escape")
    assert page.locator(".crowd-draft").count() == 0
    assert editor.session.text == text and editor.session.status()["canUndo"]


def test_a_crowd_edit_with_a_floor_that_is_not_there_is_refused_with_its_place(open_editor) -> None:
    editor: Editor = open_editor("examples/people/crowds.rei")
    status, answer = editor.call("POST", "/api/apply", {"operations": [
        {"op": "setCrowd", "name": "shoppers", "count": 12, "from": ["F_0_2", "F_99_0"], "to": ["F_12_2"],
         "rate": None}]})
    assert status == 422, answer
    assert answer["error"] == "crowd 'shoppers', from[1]: Room 'Hall' has no floor or wall named 'F_99_0'"
    status, answer = editor.call("POST", "/api/apply", {"operations": [
        {"op": "addCrowd", "name": "c2", "type": None, "count": 2, "from": ["F_6_6"], "to": "F_7_7", "rate": 1}]})
    assert status == 422 and "'to' must be a list of floor names" in answer["error"], answer
    assert not editor.session.dirty

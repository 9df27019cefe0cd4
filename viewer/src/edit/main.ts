// SPDX-License-Identifier: EPL-2.0
// The room editor page (edit.html), opened by `rei edit CASE.rei` as /edit.html?token=TOKEN. It draws the test
// case's room as SVG (elements to click, select and drag), sends every gesture to the server as operations
// (docs/room-editor.md) and draws the State the server answers. `window.reiEdit` exposes the editor's state
// for tests and the curious.
import "./edit.css";
import { byId } from "../dom";
import { Api } from "./api";
import { Chrome } from "./chrome";
import { DiagramView } from "./draw/diagram";
import { Editor } from "./editor";
import { Gestures } from "./tools/gestures";
import { installKeys } from "./tools/keys";
import { installPointer } from "./tools/pointer";

declare global {
  interface Window {
    reiEdit?: Editor;
  }
}

function start(): void {
  const chrome = new Chrome();
  const svg = byId<SVGSVGElement>("diagram");
  const diagram = new DiagramView(svg, byId("issue-labels"));
  const editor = new Editor(Api.fromLocation(window.location), diagram, chrome);
  window.reiEdit = editor;
  installPointer(svg, diagram.view, new Gestures(editor, byId("where")));
  installKeys(editor);

  const click = (id: string, action: () => void): void => chrome.button(id).addEventListener("click", action);
  click("undo", () => void editor.command("undo"));
  click("redo", () => void editor.command("redo"));
  click("save", () => void editor.command("save"));
  click("reload", () => void editor.command("reload"));
  click("keep", () => void editor.command("keep"));
  click("add-goal", () => editor.toggleGoalTool());
  click("draw-path", () => editor.startPath());
  click("finish-path", () => void editor.finishPath());
  click("cancel-path", () => editor.cancelPath());
  click("rotate-left", () => editor.rotate(90));
  click("rotate-right", () => editor.rotate(-90));
  click("delete", () => void editor.deleteSelected());
  click("fit", () => diagram.fit());

  // unsaved edits live in the server, not the page, but closing the tab is how people think they "close the file"
  window.addEventListener("beforeunload", (event) => {
    if (editor.status?.dirty === true) {
      event.preventDefault();
      event.returnValue = "";
    }
  });
  // the fit follows the first sizing of the page; a resize keeps the zoom and moves nothing
  void editor.start();
}

start();

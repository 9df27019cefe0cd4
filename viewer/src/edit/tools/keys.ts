// SPDX-License-Identifier: EPL-2.0
// Keyboard shortcuts. Keys typed into a field (a time, the yaw) belong to the field, except Ctrl+S: saving
// from anywhere is what people expect. Ctrl is Cmd on a Mac.
import type { Editor } from "../editor";

function inField(target: EventTarget | null): boolean {
  return target instanceof HTMLElement
    && (target.isContentEditable || ["INPUT", "TEXTAREA", "SELECT"].includes(target.tagName));
}

export function installKeys(editor: Editor): void {
  document.addEventListener("keydown", (event) => {
    const ctrl = event.ctrlKey || event.metaKey;
    const key = event.key.toLowerCase();
    if (ctrl && key === "s") {
      event.preventDefault();
      void editor.command("save");
      return;
    }
    if (inField(event.target)) return;
    if (ctrl && key === "z") {
      event.preventDefault();
      void editor.command(event.shiftKey ? "redo" : "undo");
    } else if (ctrl && key === "y") {
      event.preventDefault();
      void editor.command("redo");
    } else if (ctrl || event.altKey) {
      return;
    } else if (key === "escape") {
      editor.escape();
    } else if (key === "enter") {
      if (editor.drafting) {
        event.preventDefault();
        void editor.finishPath();
      }
    } else if (key === "delete" || key === "backspace") {
      event.preventDefault();
      void editor.deleteSelected();
    } else if (key === "r") {
      editor.rotate(event.shiftKey ? -90 : 90);
    }
  });
}

// SPDX-License-Identifier: EPL-2.0
// The page's frame: title and file name, the dirty indicator, which toolbar buttons apply now, the banner for a
// file changed on disk, and the toast for refusals and notices. Updated from every Status (the poll) as well
// as every State, so that the banner and the dirty mark follow the server even when the diagram did not change.
import { byId } from "../dom";
import type { Selection, Tool } from "./model";
import type { RoomIndex } from "./room";
import type { Status } from "./types";

const TOAST_MS = 6000;

export class Chrome {
  private readonly dirty = byId("dirty");
  private readonly banner = byId("disk-banner");
  private readonly bannerText = byId("disk-message");
  private readonly toastBox = byId("toast");
  private readonly link = byId("link");
  private readonly hint = byId("hint");
  private toastTimer = 0;
  private file = "";

  button(id: string): HTMLButtonElement {
    return byId<HTMLButtonElement>(id);
  }

  /** The name in the bar (the path as given can be long), the whole path on hover. */
  setFile(file: string): void {
    this.file = file;
    byId("file").textContent = file.split(/[\\/]/).pop() ?? file;
    byId("file").title = file;
  }

  /** The file's name in the title, marked while there are unsaved changes (also visible in the tab). */
  status(status: Status): void {
    const name = this.file.split(/[\\/]/).pop() ?? this.file;
    document.title = `${status.dirty ? "● " : ""}${name} — REI room editor`;
    this.dirty.hidden = !status.dirty;
    this.dirty.dataset.dirty = String(status.dirty);
    this.button("undo").disabled = !status.canUndo;
    this.button("redo").disabled = !status.canRedo;
    this.button("save").classList.toggle("attention", status.dirty);
    this.banner.hidden = !status.diskChanged;
    this.bannerText.textContent = `${name} changed on disk, and the editor has unsaved changes: which to keep?`;
    this.connected(true);
  }

  connected(ok: boolean, detail = ""): void {
    this.link.textContent = ok ? "connected" : `not connected${detail ? `: ${detail}` : ""}`;
    this.link.className = ok ? "status live" : "status disconnected";
  }

  /** Which tools apply to the selection; the others are disabled, never hidden, so the toolbar does not jump. */
  tools(index: RoomIndex | null, selection: Selection | null, tool: Tool): void {
    const kind = selection?.kind;
    const turnable = kind === "object" || kind === "robot";
    const drafting = tool.kind === "path" || tool.kind === "route" || tool.kind === "crowd";
    const layoutPart = kind === "floor" || kind === "wall";
    const deletable = kind === "object" || kind === "human" || kind === "dynamic" || kind === "goal"
      || kind === "crowd" || kind === "group"
      || (layoutPart && index?.editableLayout === true);
    this.button("rotate-left").disabled = !turnable || drafting;
    this.button("rotate-right").disabled = !turnable || drafting;
    this.button("delete").disabled = !deletable || drafting;
    this.button("delete").title = kind === "robot" ? "a room has exactly one robot: move it instead"
      : layoutPart && index?.editableLayout !== true ? "this room's floors and walls come from its size or map"
        : "delete the selection (Delete)";
    this.button("draw-path").disabled = drafting || !(kind === "human" || kind === "dynamic" || kind === "crowd");
    this.button("draw-path").title = kind === "crowd" ? "Choose the selected crowd's areas: click floors or drag"
      : "Draw the selected human's path or route: click floors";
    this.button("finish-path").disabled = !drafting;
    this.button("cancel-path").disabled = !drafting;
    this.button("add-goal").disabled = index?.diagram.mission === null || drafting;
    this.button("add-goal").classList.toggle("active", tool.kind === "goal");
    this.button("draw-path").classList.toggle("active", drafting);
  }

  showHint(text: string): void {
    this.hint.textContent = text;
    this.hint.hidden = text === "";
  }

  toast(message: string, kind: "error" | "info" = "info"): void {
    this.toastBox.textContent = message;
    this.toastBox.className = kind;
    this.toastBox.dataset.kind = kind;
    this.toastBox.hidden = false;
    window.clearTimeout(this.toastTimer);
    this.toastTimer = window.setTimeout(() => {
      this.toastBox.hidden = true;
    }, TOAST_MS);
  }
}

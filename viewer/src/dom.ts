// SPDX-License-Identifier: EPL-2.0
// A page's fixed elements by id (index.html, edit.html): a missing one is a bug of the page, said at once and by name.
export function byId<T extends Element = HTMLElement>(id: string): T {
  const found = document.getElementById(id);
  if (found === null) throw new Error(`page element #${id} is missing`);
  return found as unknown as T;
}

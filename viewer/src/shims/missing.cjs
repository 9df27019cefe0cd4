// SPDX-License-Identifier: EPL-2.0
// For optional modules autobahn-js loads in try/catch ("when"): failing to load makes it use ES6 promises.
throw new Error("not part of the live view's bundle");

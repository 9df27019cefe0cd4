// SPDX-License-Identifier: EPL-2.0
// Modules autobahn-js loads but the page never uses (cbor: a codec the router is not asked for; fs: only
// behind a Node `process` check). vite.config.ts aliases them here, keeping them and Node's streams out.
module.exports = {};

// SPDX-License-Identifier: EPL-2.0
// msgpack5's factory, as autobahn-js calls it (lib/serializer.js), answered by @msgpack/msgpack: no Node
// Buffer or streams in the page, several times faster, plain arrays and numbers, float64 +inf kept as
// Infinity (a laser beam that hit nothing). vite.config.ts aliases "msgpack5" here.
const { decode, encode } = require("@msgpack/msgpack");

module.exports = function msgpack5() {
  return { encode: (value) => encode(value), decode: (payload) => decode(payload) };
};

// Clients of sanet's Foxglove WebSocket stream, for tests/foxglove/foxglove_test.py, written from
// the protocol's side: npm's @foxglove/ws-protocol client over npm's ws (Node.js), messages decoded
// with @foxglove/rosmsg2-serialization from the schemas the server advertised. Prints JSON.
//
//   node client.mjs MODULES watch URL SECONDS TOPIC...   subscribe, collect, decode
//   node client.mjs MODULES hostile URL                  garbage, unknown operations, bad subscriptions
//   node client.mjs MODULES knock URL PROTOCOL           the HTTP status of a handshake offering PROTOCOL
import { createRequire } from "node:module";
import { resolve } from "node:path";

const [modules, mode, url, ...rest] = process.argv.slice(2);
const require = createRequire(resolve(modules) + "/");
const { FoxgloveClient } = require("@foxglove/ws-protocol");
const WebSocket = require("ws");
const { parse } = require("@foxglove/rosmsg");
const { MessageReader } = require("@foxglove/rosmsg2-serialization");

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const print = (value) => console.log(JSON.stringify(value, (k, v) => (typeof v === "bigint" ? Number(v) : v)));

function connect() {
  const ws = new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]);
  const client = new FoxgloveClient({ ws });
  const seen = { serverInfo: null, channels: new Map(), status: [], closed: null, times: [] };
  client.on("serverInfo", (info) => (seen.serverInfo = info));
  client.on("advertise", (channels) => channels.forEach((c) => seen.channels.set(c.topic, c)));
  client.on("status", (s) => seen.status.push(s));
  client.on("time", (t) => seen.times.push(t.timestamp));
  client.on("close", (e) => (seen.closed = { code: e.code, reason: String(e.reason ?? "") }));
  client.on("error", () => {});
  return { ws, client, seen };
}

async function until(check, ms = 10000) {
  for (const end = Date.now() + ms; Date.now() < end && !check(); ) await sleep(20);
  return check();
}

async function watch(seconds, topics) {
  const { client, seen } = connect();
  await until(() => topics.every((t) => seen.channels.has(t)));
  const byId = new Map(), out = {};
  for (const topic of topics) {
    const c = seen.channels.get(topic);
    if (!c) continue;
    const reader = new MessageReader(parse(c.schema, { ros2: true }));
    byId.set(client.subscribe(c.id), { topic, reader });
    out[topic] = { count: 0, stamps: [], errors: 0, schemaName: c.schemaName, encoding: c.encoding };
  }
  client.on("message", ({ subscriptionId, timestamp, data }) => {
    const { topic, reader } = byId.get(subscriptionId);
    const o = out[topic];
    o.count++;
    try {
      const m = reader.readMessage(data);
      const stamp = m.header?.stamp ?? m.transforms?.[0]?.header.stamp ?? m.markers?.[0]?.header.stamp;
      o.stamps.push([Number(timestamp), stamp ? stamp.sec * 1e9 + (stamp.nanosec ?? stamp.nsec) : null]);
      o.last = m;
    } catch (e) {
      o.errors++;
    }
  });
  await sleep(seconds * 1000);
  client.close();
  print({ serverInfo: seen.serverInfo, topics: [...seen.channels.keys()], received: out, times: seen.times,
          status: seen.status, closed: seen.closed });
}

// A handshake's outcome: the refusal's HTTP status, or "opened".
function knock(protocol) {
  return new Promise((done) => {
    const ws = new WebSocket(url, [protocol]);
    ws.on("unexpected-response", (req, res) => done(res.statusCode));
    ws.on("open", () => {
      ws.close();
      done("opened");
    });
    ws.on("error", (e) => done(`error: ${e.message}`));
  });
}

async function hostile() {
  const ws = new WebSocket(url, ["foxglove.websocket.v1"]);
  const texts = [], late = [];
  let unsubscribedAt = null;
  ws.on("message", (data, binary) => {
    if (!binary) return texts.push(JSON.parse(data.toString()));
    // Message data for subscription 1 well after it was unsubscribed (what was queued may still come).
    if (data[0] === 1 && data.readUInt32LE(1) === 1 && unsubscribedAt && Date.now() - unsubscribedAt > 300)
      late.push(Date.now() - unsubscribedAt);
  });
  await new Promise((r) => ws.on("open", r));
  await until(() => texts.some((t) => t.op === "advertise" && t.channels.some((c) => c.topic === "/tf")));
  const tf = texts.flatMap((t) => (t.op === "advertise" ? t.channels : [])).find((c) => c.topic === "/tf").id;
  const deep = "[".repeat(100000) + "]".repeat(100000);
  for (const m of ["not json", "[1, 2]", JSON.stringify({ op: "getParameters", parameterNames: [] }),
                   JSON.stringify({ op: "subscribe", subscriptions: [{ id: 1, channelId: 99999 }] }),
                   JSON.stringify({ op: "subscribe" }), JSON.stringify({ noop: 1 }),
                   `{"op":"subscribe","subscriptions":${deep}}`, `{"op":"subscribe","subscriptions":[${deep}]}`,
                   JSON.stringify({ op: "subscribe", subscriptions: [{ id: 1, channelId: tf }, { id: 2, channelId: tf }] }),
                   `{"op":"subscribe","subscriptions":[{"id":4294967297,"channelId":${tf}}]}`,
                   JSON.stringify({ op: "unsubscribe", subscriptionIds: [77] })])
    ws.send(m);
  ws.send(Buffer.from([1, 0, 0, 0, 0, 42]));
  await sleep(1000);
  ws.send(JSON.stringify({ op: "unsubscribe", subscriptionIds: [1] }));
  unsubscribedAt = Date.now();
  await sleep(1500);
  const refused = await knock("not.foxglove");
  ws.close();
  print({ statuses: texts.filter((t) => t.op === "status"), refusedWithoutSubprotocol: refused, late,
          stillOpen: ws.readyState === WebSocket.OPEN || ws.readyState === WebSocket.CLOSING });
}

if (mode === "watch") await watch(Number(rest[0]), rest.slice(1));
else if (mode === "hostile") await hostile();
else if (mode === "knock") print({ outcome: await knock(rest[0]) });
else throw new Error(`unknown mode ${mode}`);

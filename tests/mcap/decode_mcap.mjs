// Decodes every message of a ROS 2 MCAP file as a ROS 2 tool would, from the schemas in the file
// alone: @mcap/core's indexed reader (fzstd for Zstandard chunks), @foxglove/rosmsg to parse each
// ros2msg schema, @foxglove/rosmsg2-serialization to read the CDR. Each message is also written
// back with the same library's writer, which must give the same bytes (up to CDR's closing
// padding), so that a field too many or too few cannot pass. Prints JSON for the test: the
// channels, the count per topic, the decoding errors, messages whose stamp is not their log time,
// every ground-truth pose and battery state, the node events, the parent and child frames /tf links, the
// rotations of a URDF robot's moving links over time, and the first and last message of each topic
// (a large byte array, such as an image's pixels, as its SHA-256 and length).
//
//   node decode_mcap.mjs NODE_MODULES FILE [SAVE_DIR]
// With SAVE_DIR, the first message's bytes of each image topic (Image, CompressedImage) are
// written there as <topic, / as _>.bin, for a test to decode them its own way.
import { createHash } from "node:crypto";
import { createRequire } from "node:module";
import { readFile, writeFile } from "node:fs/promises";
import { resolve } from "node:path";

import * as mcapFile from "./mcap_file.mjs";

const [modules, file, saveDir] = process.argv.slice(2);
const require = createRequire(resolve(modules) + "/");
const { McapStreamReader } = require("@mcap/core");
const { parse } = require("@foxglove/rosmsg");
const { MessageReader, MessageWriter } = require("@foxglove/rosmsg2-serialization");

const decompressHandlers = mcapFile.decompressHandlers(require);
const { reader, close } = await mcapFile.openIndexed(require, file);

const codecs = new Map();  // channel id -> { reader, writer }
const channels = {};
for (const [id, c] of reader.channelsById) {
  const schema = reader.schemasById.get(c.schemaId);
  channels[c.topic] = { schema: schema.name, schemaEncoding: schema.encoding, messageEncoding: c.messageEncoding };
  const definitions = parse(new TextDecoder().decode(schema.data), { ros2: true });
  codecs.set(id, { reader: new MessageReader(definitions), writer: new MessageWriter(definitions) });
}

const stampOf = (m) => m.header?.stamp ?? m.stamp ?? m.transforms?.[0]?.header.stamp ?? m.markers?.[0]?.header.stamp;
const plain = (value) => JSON.parse(JSON.stringify(value, (k, v) =>
  typeof v === "bigint" ? Number(v) : ArrayBuffer.isView(v) ? Array.from(v) : v));
// An image's pixels as their SHA-256 and length (the first and last messages are printed whole).
const slim = (m) => m.data instanceof Uint8Array && m.data.length > 1024
  ? { ...m, data: undefined, dataLength: m.data.length, sha256: createHash("sha256").update(m.data).digest("hex") }
  : m;
const counts = {}, first = {}, last = {}, groundTruth = {}, batteries = {}, events = [], tfPairs = new Set(), urdfTracks = {};
const errors = [], stampMismatches = [];
for await (const record of reader.readMessages()) {
  const topic = reader.channelsById.get(record.channelId).topic;
  const codec = codecs.get(record.channelId);
  counts[topic] = (counts[topic] ?? 0) + 1;
  let message;
  try {
    message = codec.reader.readMessage(record.data);
    const again = codec.writer.writeMessage(message);
    const padding = record.data.length - again.length;
    if (padding < 0 || padding > 3 || !again.every((b, i) => i < 4 || b === record.data[i]))
      errors.push(`${topic}: written back as ${again.length} bytes, not ${record.data.length}`);
  } catch (e) {
    errors.push(`${topic}: ${e.message}`);
    continue;
  }
  const stamp = stampOf(message);
  // (this version of the library reads builtin_interfaces/Time as {sec, nsec})
  if (stamp && BigInt(stamp.sec) * 1000000000n + BigInt(stamp.nanosec ?? stamp.nsec) !== record.logTime)
    stampMismatches.push(`${topic} at ${record.logTime}`);
  if (record.logTime !== record.publishTime) stampMismatches.push(`${topic}: publish time differs`);
  if (topic.endsWith("/ground_truth")) {
    const p = message.pose.pose;
    (groundTruth[topic.split("/")[1]] ??= []).push(
      [Number(record.logTime) / 1e9, p.position.x, p.position.y, 2 * Math.atan2(p.orientation.z, p.orientation.w)]);
  }
  if (topic.endsWith("/battery_state"))
    (batteries[topic.split("/")[1]] ??= []).push({ t: Number(record.logTime) / 1e9, ...plain(message) });
  if (topic === "/events") events.push({ t: Number(record.logTime) / 1e9, ...plain(message) });
  if (topic === "/tf")
    for (const tf of message.transforms) {
      tfPairs.add(`${tf.header.frame_id} ${tf.child_frame_id}`);
      if (tf.child_frame_id.includes("/urdf/")) {  // a URDF robot's moving links, in full
        const r = tf.transform.rotation;
        (urdfTracks[tf.child_frame_id] ??= []).push([Number(record.logTime) / 1e9, r.x, r.y, r.z, r.w]);
      }
    }
  if (!(topic in first) && saveDir && message.data instanceof Uint8Array && (message.format ?? message.encoding))
    await writeFile(`${saveDir}/${topic.replaceAll("/", "_")}.bin`, message.data);
  first[topic] ??= plain(slim(message));
  last[topic] = slim(message);
}
for (const topic of Object.keys(last)) last[topic] = plain(last[topic]);

// In the file's own order, as a streaming reader (or a live replay) meets them: messages that go
// back in time.
const stream = new McapStreamReader({ decompressHandlers });
stream.append(new Uint8Array(await readFile(file)));
let latest = 0n, backwards = 0;
for (let r; (r = stream.nextRecord()); )
  if (r.type === "Message") {
    if (r.logTime < latest) backwards++;
    else latest = r.logTime;
  }
console.log(JSON.stringify({
  profile: reader.header.profile, channels, counts, errors: errors.slice(0, 20), errorCount: errors.length,
  stampMismatches: stampMismatches.slice(0, 20), groundTruth, batteries, events, first, last, tfPairs: [...tfPairs].sort(), urdfTracks,
  statistics: Number(reader.statistics.messageCount), chunks: reader.chunkIndexes.length,
  compression: [...new Set(reader.chunkIndexes.map((c) => c.compression))], backwards,
}));
await close();

// An independent reader of sanet's MCAP files: npm's @mcap/core (pinned by ./setup), the reader of
// Foxglove's tools. It reads FILE twice: record by record with every CRC checked
// (McapStreamReader), and through its summary and indexes (McapIndexedReader), and prints what
// it found as JSON for the test to compare. Zstandard chunks are decompressed with npm's fzstd.
//
//   node read_mcap.mjs NODE_MODULES FILE
import { createRequire } from "node:module";
import { readFile } from "node:fs/promises";
import { resolve } from "node:path";

import * as mcapFile from "./mcap_file.mjs";

const [modules, file] = process.argv.slice(2);
const require = createRequire(resolve(modules) + "/");
const { McapStreamReader } = require("@mcap/core");
const decompressHandlers = mcapFile.decompressHandlers(require);

const streamed = { records: {}, messages: 0 };
const stream = new McapStreamReader({ validateCrcs: true, decompressHandlers });
stream.append(new Uint8Array(await readFile(file)));
for (let r; (r = stream.nextRecord()); ) {
  streamed.records[r.type] = (streamed.records[r.type] ?? 0) + 1;
  if (r.type === "Message") streamed.messages++;
}
streamed.done = stream.done();

const { reader, close } = await mcapFile.openIndexed(require, file);
const channels = {};
for (const [id, c] of reader.channelsById)
  channels[c.topic] = { id, schema: reader.schemasById.get(c.schemaId)?.name, encoding: c.messageEncoding,
                        metadata: Object.fromEntries(c.metadata) };
const perTopic = {};
let previous = -1n, ordered = true;
for await (const m of reader.readMessages()) {
  const topic = reader.channelsById.get(m.channelId).topic;
  (perTopic[topic] ??= []).push([Number(m.logTime), m.sequence, m.data.length]);
  if (m.logTime < previous) ordered = false;
  previous = m.logTime;
}
const window = [];
for await (const m of reader.readMessages({ topics: ["/log"], startTime: 1000000000n, endTime: 2000000000n }))
  window.push(Number(m.logTime));
const s = reader.statistics;
console.log(JSON.stringify({
  profile: reader.header.profile, library: reader.header.library, streamed, channels,
  chunks: reader.chunkIndexes.length, compression: reader.chunkIndexes.map((c) => c.compression), summaryOffsets: [...reader.summaryOffsetsByOpcode.keys()],
  statistics: { messages: Number(s.messageCount), channels: s.channelCount, schemas: s.schemaCount,
                chunks: s.chunkCount, start: Number(s.messageStartTime), end: Number(s.messageEndTime),
                perChannel: Object.fromEntries([...s.channelMessageCounts].map(([k, v]) => [k, Number(v)])) },
  perTopic, ordered, window,
}));
await close();

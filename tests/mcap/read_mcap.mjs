// Reads an MCAP file with the independent TypeScript reader (@mcap/core's McapIndexedReader,
// CRC validation on) and prints what it found as JSON: the check that our writer follows the spec.
// Usage: node read_mcap.mjs FILE   (run where @mcap/core, @mcap/nodejs and fzstd are installed)
import { open } from "node:fs/promises";
import { McapIndexedReader } from "@mcap/core";
import { FileHandleReadable } from "@mcap/nodejs";
import { decompress } from "fzstd";

const file = process.argv[2];
const handle = await open(file, "r");
const reader = await McapIndexedReader.Initialize({
  readable: new FileHandleReadable(handle),
  decompressHandlers: { zstd: (buffer, size) => decompress(buffer, new Uint8Array(Number(size))) },
});
const topics = {};
let count = 0;
for await (const message of reader.readMessages({ validateCrcs: true })) {
  const channel = reader.channelsById.get(message.channelId);
  topics[channel.topic] = (topics[channel.topic] ?? 0) + 1;
  count++;
}
const schemas = [...reader.schemasById.values()].map((s) => ({ name: s.name, encoding: s.encoding }));
const encodings = [...new Set([...reader.channelsById.values()].map((c) => c.messageEncoding))];
const metadata = {};
for await (const m of reader.readMetadata()) metadata[m.name] = Object.fromEntries(m.metadata);
console.log(JSON.stringify({
  count,
  topics,
  schemas,
  encodings,
  chunks: reader.chunkIndexes.length,
  statistics_count: Number(reader.statistics?.messageCount ?? -1),
  metadata,
}));
await handle.close();

// What the tests' MCAP readers share: npm's fzstd for Zstandard chunks, and a file opened for
// @mcap/core's indexed reader (which reads ranges of it as it seeks).
import { open } from "node:fs/promises";

export function decompressHandlers(require) {
  const { decompress } = require("fzstd");
  return { zstd: (data, size) => decompress(data, new Uint8Array(Number(size))) };
}

// { reader, close }: the indexed reader over `file`, and what closes the file.
export async function openIndexed(require, file) {
  const { McapIndexedReader } = require("@mcap/core");
  const handle = await open(file);
  const readable = {
    size: async () => BigInt((await handle.stat()).size),
    read: async (offset, length) => {
      const buffer = Buffer.alloc(Number(length));
      await handle.read(buffer, 0, Number(length), Number(offset));
      return new Uint8Array(buffer.buffer, buffer.byteOffset, buffer.length);
    },
  };
  const reader = await McapIndexedReader.Initialize({ readable, decompressHandlers: decompressHandlers(require) });
  return { reader, close: () => handle.close() };
}

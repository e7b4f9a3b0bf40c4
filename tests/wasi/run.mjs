// Runs a wasm32-wasip1 test binary under Node.js's built-in WASI (preview 1): the cargo runner
// for this package. Exit status is the program's.
import { readFile } from 'node:fs/promises';
import { WASI } from 'node:wasi';
import process from 'node:process';

const [wasmPath, ...args] = process.argv.slice(2);
const wasi = new WASI({
  version: 'preview1',
  args: [wasmPath, ...args],
  env: process.env,
  returnOnExit: true,
});
const module = await WebAssembly.compile(await readFile(wasmPath));
const instance = await WebAssembly.instantiate(module, wasi.getImportObject());
// Exit at once: with simd128 modules, Node 20 has crashed (SIGSEGV) in its teardown after the
// program had returned.
process.exit(wasi.start(instance));

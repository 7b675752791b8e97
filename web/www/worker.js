// The page's worker: runs gdsmc (gdsmc_web.wasm, the runner built for WebAssembly) off the
// page's thread, so the page stays responsive. Messages in: {type: "run", name, text, sets},
// {type: "stop"}. Messages out: "kinds", "prepared", "progress" (with the charts so far),
// "done" (summary, files, timing), "error" (the command's words).
"use strict";

// The few WASI calls the Rust standard library links: output goes to the console, a clock and
// random bytes from the browser, and everything else (files, the environment) is absent.
const ENOSYS = 52;
let memory = null;
let stderrLine = "";
const wasi = {
  fd_write(fd, iovs, iovsLen, written) {
    const view = new DataView(memory.buffer);
    let n = 0;
    for (let i = 0; i < iovsLen; i++) {
      const ptr = view.getUint32(iovs + 8 * i, true);
      const len = view.getUint32(iovs + 8 * i + 4, true);
      stderrLine += new TextDecoder().decode(new Uint8Array(memory.buffer, ptr, len));
      n += len;
    }
    const lines = stderrLine.split("\n");
    stderrLine = lines.pop();
    for (const l of lines) console.log(`gdsmc (fd ${fd}): ${l}`);
    view.setUint32(written, n, true);
    return 0;
  },
  environ_sizes_get(count, size) {
    const view = new DataView(memory.buffer);
    view.setUint32(count, 0, true);
    view.setUint32(size, 0, true);
    return 0;
  },
  environ_get() { return 0; },
  args_sizes_get(count, size) { return wasi.environ_sizes_get(count, size); },
  args_get() { return 0; },
  random_get(ptr, len) {
    crypto.getRandomValues(new Uint8Array(memory.buffer, ptr, len));
    return 0;
  },
  clock_time_get(id, precision, out) {
    const ns = BigInt(Math.round((performance.timeOrigin + performance.now()) * 1e6));
    new DataView(memory.buffer).setBigUint64(out, ns, true);
    return 0;
  },
  proc_exit(code) { throw new Error(`gdsmc exited with ${code}`); },
};
const imports = {
  wasi_snapshot_preview1: new Proxy(wasi, {
    get: (target, name) => target[name] || (() => ENOSYS),
  }),
};

let gdsmc = null;

async function load() {
  const { instance } = await WebAssembly.instantiateStreaming(fetch("gdsmc_web.wasm"), imports);
  gdsmc = instance.exports;
  memory = gdsmc.memory;
  if (gdsmc._initialize) gdsmc._initialize();
}

const encoder = new TextEncoder();
const decoder = new TextDecoder();

// Calls an export; returns [status, text of the answer]. A trap (a panic) becomes an error
// with the panic's message, and the module is loaded afresh for the next run.
function call(name, ...args) {
  try {
    const status = gdsmc[name](...args);
    const ptr = gdsmc.gdsmc_web_output();
    const len = gdsmc.gdsmc_web_output_len();
    return [status, decoder.decode(new Uint8Array(memory.buffer, ptr, len))];
  } catch (e) {
    let message = String(e);
    try {
      gdsmc.gdsmc_web_panic();
      const ptr = gdsmc.gdsmc_web_output();
      const len = gdsmc.gdsmc_web_output_len();
      const panic = decoder.decode(new Uint8Array(memory.buffer, ptr, len));
      if (panic) message = `internal error (please report it): ${panic}`;
    } catch (_) { /* the module is gone */ }
    gdsmc = null;
    return [-1, message];
  }
}

function prepare(name, text, sets) {
  const parts = [name, text, sets].map((s) => encoder.encode(s));
  const total = parts.reduce((n, p) => n + p.length, 0);
  const at = gdsmc.gdsmc_web_input(total);
  let offset = at;
  for (const p of parts) {
    new Uint8Array(memory.buffer, offset, p.length).set(p);
    offset += p.length;
  }
  return call("gdsmc_web_prepare", parts[0].length, parts[1].length, parts[2].length);
}

let stopAsked = false;
const yieldToEvents = () => new Promise((resolve) => setTimeout(resolve, 0));

async function run({ name, text, sets }) {
  stopAsked = false;
  if (!gdsmc) await load();
  const [status, answer] = prepare(name, text, sets);
  if (status !== 0) return postMessage({ type: "error", message: answer });
  const info = JSON.parse(answer);
  postMessage({ type: "prepared", info });
  // Chunks of ensembles sized to take about a tenth of a second, so "stop" is heard soon.
  let chunk = 1;
  let done = 0;
  let busy = 0; // milliseconds spent in the engine (the worker's thread does nothing else)
  let lastDraw = 0;
  while (done < info.ensembles && !stopAsked) {
    const t0 = performance.now();
    const [s, a] = call("gdsmc_web_advance", chunk);
    const took = performance.now() - t0;
    busy += took;
    if (s !== 0) return postMessage({ type: "error", message: a });
    done = JSON.parse(a).done;
    chunk = Math.max(1, Math.min(1024, Math.round((chunk * 100) / Math.max(took, 1))));
    if (performance.now() - lastDraw > 400 || done === info.ensembles) {
      const [cs, charts] = call("gdsmc_web_charts");
      if (cs === 0) postMessage({ type: "progress", done, ...JSON.parse(charts) });
      lastDraw = performance.now();
    } else {
      postMessage({ type: "progress", done, ensembles: info.ensembles });
    }
    await yieldToEvents();
  }
  const [s, a] = call("gdsmc_web_finish");
  if (s !== 0) return postMessage({ type: "error", message: a });
  const result = JSON.parse(a);
  const [, charts] = call("gdsmc_web_charts");
  postMessage({
    charts: JSON.parse(charts).charts,
    type: "done",
    info,
    stopped: stopAsked && result.done < info.ensembles,
    engine_seconds: busy / 1000,
    ...result,
  });
}

onmessage = async (e) => {
  const m = e.data;
  if (m.type === "stop") stopAsked = true;
  else if (m.type === "run") await run(m);
  else if (m.type === "kinds") {
    if (!gdsmc) await load();
    const [, k] = call("gdsmc_web_kinds");
    postMessage({ type: "kinds", kinds: JSON.parse(k) });
  }
};

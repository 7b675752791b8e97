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
let compiled = null; // the module, compiled once and handed to the helpers

// Compiles the module as it downloads; a server that does not call it application/wasm gets
// it compiled after the download instead.
async function compile() {
  try {
    return await WebAssembly.compileStreaming(fetch("gdsmc_web.wasm"));
  } catch (_) {
    return WebAssembly.compile(await (await fetch("gdsmc_web.wasm")).arrayBuffer());
  }
}

async function load(module) {
  compiled = module || compiled || (await compile());
  const instance = await WebAssembly.instantiate(compiled, imports);
  gdsmc = instance.exports;
  memory = gdsmc.memory;
  if (gdsmc._initialize) gdsmc._initialize();
}

const encoder = new TextEncoder();
const decoder = new TextDecoder();

// Calls an export; returns [status, text of the answer]. A trap (a panic) becomes an error
// with the panic's message, and the module is loaded afresh for the next run.
function call(name, ...args) {
  return callAs(false, name, ...args);
}

// As `call`, the answer as bytes (an ArrayBuffer) when `binary` and the call succeeded.
function callAs(binary, name, ...args) {
  try {
    const status = gdsmc[name](...args);
    const ptr = gdsmc.gdsmc_web_output();
    const len = gdsmc.gdsmc_web_output_len();
    if (binary && status === 0) return [status, memory.buffer.slice(ptr, ptr + len)];
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

// Helpers: as many workers as the machine has cores (at most 16), when a worker may start
// workers; else this worker runs every ensemble itself.
function helperCount(ensembles) {
  const cores = (self.navigator && navigator.hardwareConcurrency) || 1;
  if (typeof Worker === "undefined" || cores < 2) return 0;
  return Math.min(cores, 16, ensembles);
}

async function run({ name, text, sets }) {
  stopAsked = false;
  if (!gdsmc) await load();
  const [status, answer] = prepare(name, text, sets);
  if (status !== 0) return postMessage({ type: "error", message: answer });
  const info = JSON.parse(answer);
  postMessage({ type: "prepared", info });
  const helpers = helperCount(info.ensembles);
  if (helpers > 0) return runWithHelpers(info, { name, text, sets }, helpers);
  // Chunks of ensembles sized to take about a tenth of a second, so "stop" is heard soon.
  let chunk = 1;
  let done = 0;
  let busy = 0; // milliseconds spent in the engine (the worker's thread does nothing else)
  let nextDraw = 0;
  while (done < info.ensembles && !stopAsked) {
    const t0 = performance.now();
    const [s, a] = call("gdsmc_web_advance", chunk);
    const took = performance.now() - t0;
    busy += took;
    if (s !== 0) return postMessage({ type: "error", message: a });
    done = JSON.parse(a).done;
    chunk = Math.max(1, Math.min(1024, Math.round((chunk * 100) / Math.max(took, 1))));
    if (performance.now() > nextDraw || done === info.ensembles) {
      nextDraw = draw(done);
    } else {
      postMessage({ type: "progress", done, ensembles: info.ensembles });
    }
    await yieldToEvents();
  }
  finish(info, { engine_seconds: busy / 1000, wall_seconds: busy / 1000, workers: 1 });
}

// Posts the charts of the ensembles folded so far; returns when to draw next: after 0.4 s, or
// ten times as long as drawing took, so that drawing costs at most a tenth of this worker.
function draw(done) {
  const t0 = performance.now();
  const [cs, charts] = call("gdsmc_web_charts");
  if (cs === 0) postMessage({ type: "progress", done, ...JSON.parse(charts) });
  const took = performance.now() - t0;
  return performance.now() + Math.max(400, 10 * took);
}

// The end of a run: the summary, tables and charts of the ensembles folded.
function finish(info, timing) {
  const [s, a] = call("gdsmc_web_finish");
  if (s !== 0) return postMessage({ type: "error", message: a });
  const result = JSON.parse(a);
  const [, charts] = call("gdsmc_web_charts");
  postMessage({
    charts: JSON.parse(charts).charts,
    type: "done",
    info,
    stopped: stopAsked && result.done < info.ensembles,
    ...timing,
    ...result,
  });
}

// The run spread over helper workers: each prepares the same scene and runs the ensembles it
// is handed (ensemble k from the seed's stream jumped k times, as the command's threads do);
// this worker folds them in ensemble order as they come back (the command's fold, so its
// bits), draws, and hands out more. Stop ends the hand-out and the helpers at once: the
// ensembles folded are an unbroken prefix, a run of that many.
function runWithHelpers(info, scene, count) {
  const start = performance.now();
  const waiting = new Map(); // ensemble -> its bytes, until its turn to be folded
  let next = 0; // the next ensemble to hand out
  let done = 0; // folded
  let seconds = 0; // the helpers' time in the engine
  let nextDraw = 0;
  let ended = false;
  const pool = [];
  const end = (error) => {
    if (ended) return;
    ended = true;
    for (const h of pool) h.worker.terminate();
    if (error) return postMessage({ type: "error", message: error });
    const wall = (performance.now() - start) / 1000;
    call("gdsmc_web_add_time", wall, seconds);
    finish(info, { engine_seconds: seconds, wall_seconds: wall, workers: count });
  };
  const handOut = (h) => {
    if (stopAsked || next >= info.ensembles) {
      h.busy = false;
      if (stopAsked || pool.every((p) => !p.busy)) end();
      return;
    }
    const n = Math.min(h.batch, info.ensembles - next);
    h.worker.postMessage({ type: "ensembles", from: next, count: n });
    h.busy = true;
    next += n;
  };
  const fold = () => {
    while (waiting.has(done)) {
      const bytes = new Uint8Array(waiting.get(done));
      waiting.delete(done);
      new Uint8Array(memory.buffer, gdsmc.gdsmc_web_input(bytes.length), bytes.length).set(bytes);
      const [s, a] = call("gdsmc_web_fold", bytes.length);
      if (s !== 0) return end(a);
      done = JSON.parse(a).done;
    }
    if (performance.now() > nextDraw) {
      nextDraw = draw(done);
    } else {
      postMessage({ type: "progress", done, ensembles: info.ensembles });
    }
  };
  stopHook = () => end();
  for (let i = 0; i < count; i++) {
    const h = { worker: new Worker("worker.js"), batch: 1, busy: true };
    pool.push(h);
    h.worker.onmessage = (e) => {
      const m = e.data;
      if (ended) return;
      if (m.type === "ready") return handOut(h);
      if (m.type === "error") return end(m.message);
      // m.type === "rows": a batch done; the next sized to take about a tenth of a second.
      seconds += m.seconds;
      h.batch = Math.max(1, Math.min(1024, Math.round((m.rows.length * 0.1) / Math.max(m.seconds, 1e-3))));
      m.rows.forEach((r, k) => waiting.set(m.from + k, r));
      fold();
      if (!ended) handOut(h);
    };
    h.worker.onerror = (e) => end(`a helper worker failed: ${e.message}`);
    h.worker.postMessage({ type: "helper", module: compiled, ...scene });
  }
}
let stopHook = null;

// A helper: the scene prepared once, then the ensembles it is handed, each run alone.
async function help(m) {
  if (m.type === "helper") {
    if (!gdsmc) await load(m.module);
    const [status, answer] = prepare(m.name, m.text, m.sets);
    return postMessage(status === 0 ? { type: "ready" } : { type: "error", message: answer });
  }
  const t0 = performance.now();
  const rows = [];
  for (let k = m.from; k < m.from + m.count; k++) {
    const [s, a] = callBytes("gdsmc_web_ensemble", k);
    if (s !== 0) return postMessage({ type: "error", message: a });
    rows.push(a);
  }
  const seconds = (performance.now() - t0) / 1000;
  postMessage({ type: "rows", from: m.from, rows, seconds }, rows);
}

// As `call`, for an answer in bytes: [status, ArrayBuffer] (or the error's words).
function callBytes(name, ...args) {
  return callAs(true, name, ...args);
}

onmessage = async (e) => {
  const m = e.data;
  if (m.type === "stop") {
    stopAsked = true;
    if (stopHook) stopHook();
  } else if (m.type === "run") {
    stopHook = null;
    await run(m);
  } else if (m.type === "helper" || m.type === "ensembles") await help(m);
  else if (m.type === "kinds") {
    if (!gdsmc) await load();
    const [, k] = call("gdsmc_web_kinds");
    postMessage({ type: "kinds", kinds: JSON.parse(k) });
  }
};

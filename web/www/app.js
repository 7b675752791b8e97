// The page: picks a scene, gathers the keys the user set (as `gdsmc run --set` would take
// them), runs it in the worker (worker.js), draws the command's own charts as the ensembles
// come in, and shows the command's summary with its verdicts and the files to download.
"use strict";

const $ = (id) => document.getElementById(id);
const worker = new Worker("worker.js");
let scenes = [];
let kinds = null;
let listeners = []; // test mode: who waits for the next "done" or "error"
let onProgress = null; // test mode: sees each progress message

// --- the scene and the keys -----------------------------------------------------------

function selectedScene() {
  return scenes.find((s) => s.name === $("scene").value);
}

function showScene() {
  const s = selectedScene();
  $("toml").value = s.text;
  const d = s.text.match(/^description\s*=\s*"(.*)"\s*$/m);
  $("description").textContent = d ? d[1] : "";
}

// Inputs for the declared parameters of the chosen kernel or drive (their rule and words
// from the core's declarations, as the scene's validation has them).
function showParams(select, table, prefix, target) {
  target.textContent = "";
  const kind = (kinds ? kinds[table] : []).find((k) => k.name === select.value);
  if (!kind) return;
  select.title = kind.doc;
  for (const p of kind.params || []) {
    const label = document.createElement("label");
    label.title = `${p.words} (${p.rule}${p.unit ? ", " + p.unit : ""})`;
    label.innerHTML = `${p.name} <code>${prefix}.${p.name}</code>`;
    const input = document.createElement("input");
    input.dataset.key = `${prefix}.${p.name}`;
    input.placeholder = p.default === null ? `e.g. ${p.example}` : `${p.default}`;
    label.append(input);
    target.append(label);
  }
}

// The overrides in the order the form shows them, then the free lines: what the command's
// `--set` would get, one a line.
function overrides() {
  const sets = [];
  for (const el of $("keys").querySelectorAll("[data-key]")) {
    const v = el.value.trim();
    if (v === "") continue;
    const quoted = el.tagName === "SELECT" ? JSON.stringify(v) : v;
    sets.push(`${el.dataset.key}=${quoted}`);
  }
  if ($("distribution").checked && !/^\s*\[reduced_histogram\]/m.test($("toml").value)) {
    sets.push("reduced_histogram.shells=40", "reduced_histogram.radius=4");
  }
  for (const line of $("sets").value.split("\n")) if (line.trim()) sets.push(line.trim());
  return sets;
}

// --- running --------------------------------------------------------------------------

function start() {
  const s = selectedScene();
  $("error").hidden = true;
  $("result").hidden = true;
  $("run").disabled = true;
  $("stop").disabled = false;
  $("progress").value = 0;
  $("status").textContent = "starting";
  for (const i of [0, 1, 2]) $(`chart-${i}`).textContent = "";
  // An edited file is named as such in errors (its lines are not the shipped file's).
  const edited = $("toml").value !== s.text;
  const name = edited ? `${s.path} (edited)` : s.path;
  const sets = overrides();
  worker.postMessage({ type: "run", name, text: $("toml").value, sets: sets.join("\n") });
  if (location.hash !== "#test") history.replaceState(null, "", link(s.name, sets, edited));
}

// The page's address for this run: the scene, its keys and an edited file, so that a link
// opens the page set up for the same run (the seed is a key like any other).
function link(scene, sets, edited) {
  const q = new URLSearchParams({ scene });
  for (const x of sets) q.append("set", x);
  if (edited) q.append("text", $("toml").value);
  return `#${q.toString()}`;
}

// Sets the page up from an address made by `link`: the scene, its file if edited, and every
// key as a line of "More keys".
function fromLink() {
  const q = new URLSearchParams(location.hash.slice(1));
  const s = scenes.find((x) => x.name === q.get("scene"));
  if (!s) return;
  $("scene").value = s.name;
  showScene();
  if (q.has("text")) $("toml").value = q.get("text");
  for (const el of $("keys").querySelectorAll("[data-key]")) el.value = "";
  $("kernel-params").textContent = "";
  $("drive-params").textContent = "";
  $("distribution").checked = false;
  $("sets").value = q.getAll("set").join("\n");
}

// The charts shown live: the one the user watches (the Watch list, every chart of the run),
// then the temperature about the flow (the granular temperature; the raw T keeps the initial
// sample's centre-of-mass energy), a2 and the distribution when there is one.
function liveStems(charts) {
  const watch = $("watch");
  const names = Object.keys(charts);
  if (watch.options.length !== names.length || [...watch.options].some((o, i) => o.value !== names[i])) {
    const chosen = watch.value;
    watch.textContent = "";
    for (const n of names) watch.append(new Option(n, n));
    watch.value = names.includes(chosen) ? chosen : (names.includes("T_bulk") ? "T_bulk" : names[0]);
    $("watching").hidden = false;
  }
  const want = [watch.value, "T_bulk", "a2", "reduced", "T", "v4"];
  const stems = [...new Set(want)].filter((s) => s in charts);
  for (const s of Object.keys(charts)) if (stems.length < 3 && !stems.includes(s)) stems.push(s);
  return stems.slice(0, 3);
}

let lastCharts = null;

function drawLive(charts) {
  lastCharts = charts;
  liveStems(charts).forEach((stem, i) => { $(`chart-${i}`).innerHTML = charts[stem]; });
}

function download(name, text, type) {
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([text], { type }));
  a.download = name;
  a.textContent = name;
  return a;
}

function finished(m) {
  $("run").disabled = false;
  $("stop").disabled = true;
  $("result").hidden = false;
  $("progress").value = m.done / m.info.ensembles;
  $("status").textContent = m.stopped
    ? `stopped: ${m.done} of ${m.info.ensembles} ensembles (the statistics are those of a run of ${m.done})`
    : `${m.done} ensembles`;
  $("summary").textContent = m.summary;
  const rate = m.collisions / Math.max(m.wall_seconds, 1e-9);
  const each = m.collisions / Math.max(m.engine_seconds, 1e-9);
  $("speed").textContent = `${m.collisions.toLocaleString("en")} collisions in ` +
    `${m.wall_seconds.toFixed(2)} s: ${rate.toExponential(3)} collisions/s on ${m.workers} ` +
    `worker${m.workers > 1 ? "s" : ""} (WebAssembly; ${each.toExponential(3)} per worker-second).`;
  const links = $("downloads");
  links.textContent = "";
  links.append(download(`${m.info.scene}.toml`, m.info.toml, "application/toml"));
  links.append(download("summary.txt", m.summary, "text/plain"));
  for (const [name, text] of Object.entries(m.files)) {
    links.append(download(name, text, name.endsWith(".json") ? "application/json" : "text/csv"));
  }
  $("reproduce").innerHTML = `<code>gdsmc run ${m.info.scene}.toml</code> with the scene file above ` +
    `reproduces these numbers to the last bit (streams v${m.info.stream_version}); ` +
    `<a href="${location.href}">this page's address</a> opens it set up for the same run.`;
}

worker.onmessage = (e) => {
  const m = e.data;
  if (m.type === "kinds") {
    kinds = m.kinds;
    $("version").textContent = `${kinds.version} (streams v${kinds.stream_version})`;
    for (const [sel, table] of [["kernel", "kernels"], ["drive", "drives"]]) {
      for (const k of kinds[table]) {
        const o = document.createElement("option");
        o.value = k.name;
        o.textContent = k.name;
        o.title = k.doc;
        $(sel).append(o);
      }
    }
  } else if (m.type === "prepared") {
    $("status").textContent = `0 of ${m.info.ensembles} ensembles of n = ${m.info.n}`;
  } else if (m.type === "progress") {
    $("progress").value = m.done / m.ensembles;
    $("status").textContent = `${m.done} of ${m.ensembles} ensembles`;
    if (m.charts) drawLive(m.charts);
    if (onProgress) onProgress(m);
  } else if (m.type === "done") {
    drawLive(m.charts);
    finished(m);
    $("more").innerHTML = Object.values(m.charts).join("");
  } else if (m.type === "error") {
    $("run").disabled = false;
    $("stop").disabled = true;
    $("status").textContent = "";
    $("error").hidden = false;
    $("error").textContent = m.message;
  }
  if (m.type === "done" || m.type === "error") {
    const waiting = listeners;
    listeners = [];
    for (const l of waiting) l(m);
  }
};

$("scene").onchange = showScene;
$("kernel").onchange = () => showParams($("kernel"), "kernels", "collisions", $("kernel-params"));
$("drive").onchange = () => showParams($("drive"), "drives", "drive", $("drive-params"));
$("run").onclick = start;
$("watch").onchange = () => { if (lastCharts) drawLive(lastCharts); };
$("stop").onclick = () => worker.postMessage({ type: "stop" });

// --- test mode (web/test/browser.py): #test runs the cases of cases.json through the form
// and posts what the page showed to /report -----------------------------------------------

// What a reader sees at this window's width: the page's own width against the window's (no
// sideways scrolling), and each live chart's drawn width and its smallest text in pixels (its
// tick labels' font size scaled as the chart is).
function layout() {
  const charts = [0, 1, 2].map((i) => $(`chart-${i}`).querySelector("svg")).filter(Boolean);
  return {
    window: window.innerWidth,
    page: document.documentElement.scrollWidth,
    charts: charts.map((svg) => {
      const drawn = svg.getBoundingClientRect().width;
      const own = Number(svg.getAttribute("width"));
      const sizes = [...svg.querySelectorAll("text")].map((t) => Number(t.getAttribute("font-size")));
      return { drawn, smallest_text: Math.min(...sizes) * drawn / own };
    }),
    watch: $("watch").options.length,
  };
}

async function runTests() {
  const cases = await (await fetch("cases.json")).json();
  const results = [];
  for (const c of cases) {
    $("scene").value = c.scene;
    showScene();
    for (const el of $("keys").querySelectorAll("[data-key]")) el.value = "";
    for (const [id, v] of Object.entries(c.fields || {})) $(id).value = v;
    $("distribution").checked = c.distribution !== false;
    $("sets").value = (c.sets || []).join("\n");
    const done = new Promise((resolve) => listeners.push(resolve));
    // A case with `stop` presses Stop once that many ensembles are done.
    onProgress = c.stop ? (p) => { if (p.done >= c.stop) { onProgress = null; $("stop").click(); } } : null;
    $("run").click();
    const m = await done;
    onProgress = null;
    // The run's address, opened again, sets the page up for the same keys.
    const sets = overrides();
    const edited = $("toml").value !== selectedScene().text;
    const saved = location.hash;
    history.replaceState(null, "", link(c.scene, sets, edited));
    fromLink();
    const linked = { scene: $("scene").value, sets: overrides() };
    history.replaceState(null, "", saved);
    results.push({
      name: c.name,
      link_ok: linked.scene === c.scene && JSON.stringify(linked.sets) === JSON.stringify(sets),
      sets,
      error: m.type === "error" ? $("error").textContent : null,
      summary: m.type === "done" ? $("summary").textContent : null,
      files: m.files || null,
      toml: m.info ? m.info.toml : null,
      done: m.done || 0,
      stopped: Boolean(m.stopped),
      status: $("status").textContent,
      collisions: m.collisions || 0,
      engine_seconds: m.engine_seconds || 0,
      wall_seconds: m.wall_seconds || 0,
      workers: m.workers || 0,
      charts_live: [0, 1, 2].map((i) => $(`chart-${i}`).innerHTML.startsWith("<svg")),
      layout: layout(),
    });
  }
  await fetch("report", { method: "POST", body: JSON.stringify(results) });
}

(async () => {
  scenes = await (await fetch("scenes.json")).json();
  for (const s of scenes) {
    const o = document.createElement("option");
    o.value = s.name;
    o.textContent = s.name;
    $("scene").append(o);
  }
  $("scene").value = scenes.some((s) => s.name === "grw-example3") ? "grw-example3" : scenes[0].name;
  showScene();
  worker.postMessage({ type: "kinds" });
  if (location.hash === "#test") runTests();
  else if (location.hash.startsWith("#scene=")) fromLink();
})();

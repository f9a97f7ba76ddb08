// The sanet viewer: replays a run's trace (served as /api/... by `sanet view`) with three.js and
// Chart.js (the controllers' metrics in metrics.js, the radios' ranges in ranges.js). The page opens
// paused at ?t=SECONDS. window.sanet is a small API for tests and scripts: ready, seek(t), state(),
// select(name), ranges().
"use strict";

const api = (path) => fetch(path).then((r) => { if (!r.ok) throw new Error(path + ": " + r.status); return r.json(); });

const view = { t: 0, playing: false, selected: null, frames: [], framesFrom: -1, routes: [], routesAt: -1 };

// The pose of a node at time t, between its recorded samples (docs/trace.md: poses).
function poseAt(rows, t) {
  if (!rows || rows.length === 0) return null;
  if (t <= rows[0][0]) return rows[0];
  let lo = 0, hi = rows.length - 1;
  while (lo < hi) { const mid = (lo + hi + 1) >> 1; if (rows[mid][0] <= t) lo = mid; else hi = mid - 1; }
  const a = rows[lo], b = rows[lo + 1];
  if (!b) return a;
  const f = (t - a[0]) / (b[0] - a[0]);
  return [t, a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]), a[3] + f * (b[3] - a[3])];
}

// Batteries: a node with energy is drawn in viridis, from full (yellow-green) to empty (purple),
// and dark grey once dead; viridis keeps its order for colour-blind eyes and in grey. The scale
// stops short of its dark end, which a dead node's grey would be mistaken for.
const chargeScale = ["#482475", "#414487", "#355f8d", "#2a788e", "#21918c", "#22a884", "#44bf70", "#7ad151", "#bddf26"];
const deadColor = "#404040";

function chargeColor(fraction) {
  const f = Math.max(0, Math.min(1, fraction)) * (chargeScale.length - 1);
  const i = Math.min(chargeScale.length - 2, Math.floor(f));
  return new THREE.Color(chargeScale[i]).lerp(new THREE.Color(chargeScale[i + 1]), f - i);
}

// A node's colour: by its charge (a fraction; null: no battery) or dead, else its model's own.
function paint(n, charge, dead) {
  n.charge = charge; n.dead = dead;
  if (dead) n.mesh.material.color.set(deadColor);
  else if (charge !== null) n.mesh.material.color.copy(chargeColor(charge));
  else n.mesh.material.color.setHex(n.color);
}

// The scale's legend, shown once some node has a battery.
function showLegend() {
  const legend = document.getElementById("legend");
  if (!legend.hidden) return;
  const stops = chargeScale.map((c, i) => `${c} ${(100 * i) / (chargeScale.length - 1)}%`).join(", ");
  legend.innerHTML = `battery: empty <span class="scale" style="background: linear-gradient(to right, ${stops})"></span> full` +
    ` <span class="swatch" style="background: ${deadColor}"></span> dead`;
  legend.hidden = false;
}

// The latest of rows ([t, ...], in time order) at or before t, or null.
function latest(rows, t) {
  if (!rows.length || rows[0][0] > t) return null;
  let lo = 0, hi = rows.length - 1;
  while (lo < hi) { const mid = (lo + hi + 1) >> 1; if (rows[mid][0] <= t) lo = mid; else hi = mid - 1; }
  return rows[lo];
}

function bounds(run, poses) {
  const xs = [], ys = [];
  for (const n of run.nodes) { xs.push(n.x); ys.push(n.y); }
  for (const rows of Object.values(poses)) for (const p of rows) { xs.push(p[1]); ys.push(p[2]); }
  for (const o of run.obstacles) { xs.push(o[1]); ys.push(o[2]); }
  const box = { x0: Math.min(...xs), x1: Math.max(...xs), y0: Math.min(...ys), y1: Math.max(...ys) };
  box.size = Math.max(box.x1 - box.x0, box.y1 - box.y0, 1);
  box.cx = (box.x0 + box.x1) / 2; box.cy = (box.y0 + box.y1) / 2;
  return box;
}

function buildScene(run, poses, box) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xffffff);
  scene.add(new THREE.AmbientLight(0xffffff, 0.7));
  const sun = new THREE.DirectionalLight(0xffffff, 0.5); sun.position.set(1, -1, 2); scene.add(sun);
  const grid = new THREE.GridHelper(box.size * 1.2, 12, 0xdddddd, 0xeeeeee);
  grid.rotation.x = Math.PI / 2; grid.position.set(box.cx, box.cy, -0.01); scene.add(grid);
  for (const [kind, cx, cy, length, width, height, yaw] of run.obstacles) {
    const mesh = new THREE.Mesh(new THREE.BoxGeometry(length, width, height),
                                new THREE.MeshLambertMaterial({ color: kind === "wall" || kind === "map" ? 0x777777 : 0x999999 }));
    mesh.position.set(cx, cy, height / 2); mesh.rotation.z = yaw; scene.add(mesh);
  }
  const moteSize = Math.max(0.1, box.size / 120), robotSize = Math.max(0.4, box.size / 70);
  const nodes = run.nodes.map((n) => {
    const mote = n.model === "mote";
    const geometry = mote ? new THREE.BoxGeometry(moteSize, moteSize, moteSize)
                          : new THREE.CylinderGeometry(robotSize / 2, robotSize / 2, robotSize / 2, 20).rotateX(Math.PI / 2);
    const color = mote ? 0x2060c0 : 0xd04010;
    const mesh = new THREE.Mesh(geometry, new THREE.MeshLambertMaterial({ color }));
    mesh.userData = n; scene.add(mesh);
    const label = document.createElement("div");
    label.className = "label" + (mote ? "" : " robot"); label.textContent = n.name;
    document.getElementById("labels").appendChild(label);
    let track = null;
    const rows = poses[n.id] || [];
    if (!mote && rows.length > 1) {
      const points = rows.map((p) => new THREE.Vector3(p[1], p[2], 0.02));
      track = new THREE.Line(new THREE.BufferGeometry().setFromPoints(points),
                             new THREE.LineBasicMaterial({ color: 0xe08060 }));
      scene.add(track);
    }
    return { node: n, mesh, label, track, rows, mote, color, state: "", charge: null, dead: false };
  });
  return { scene, nodes };
}

function cameras(box, element) {
  const aspect = element.clientWidth / Math.max(1, element.clientHeight);
  const half = box.size * 0.6;
  const top = new THREE.OrthographicCamera(-half * aspect, half * aspect, half, -half, -1000, 1000);
  top.position.set(box.cx, box.cy, 100);
  const perspective = new THREE.PerspectiveCamera(50, aspect, 0.1, box.size * 20);
  perspective.up.set(0, 0, 1);
  perspective.position.set(box.cx - box.size * 0.8, box.cy - box.size * 1.3, box.size * 1.0);
  return { top, perspective };
}

// Radio links heard in the last second, and data frames in flight in the last 0.3 s (hop by hop).
async function frameWindow(t) {
  const from = Math.floor(t * 2) / 2 - 1;
  if (from !== view.framesFrom) {
    view.framesFrom = from;
    view.frames = await api(`/api/frames?from=${from}&to=${from + 1.5}`);
  }
  return view.frames.filter((f) => f[0] <= t && f[0] > t - 1);
}

function drawRadio(world, frames, t) {
  for (const line of world.radio) world.scene.remove(line);
  world.radio = [];
  const position = (id) => world.nodes[id].mesh.position;
  const links = new Set();
  for (const [ft, node, tx, peer, kind] of frames) {
    if (tx && peer === null && t - ft < 0.3 && (kind === "broadcast" || kind === "routing") && world.nodes[node]) {
      // A frame sent to all in range: a ring that widens from its sender.
      const ring = new THREE.Mesh(new THREE.RingGeometry(world.dotSize * (1 + 20 * (t - ft)), world.dotSize * (1.6 + 20 * (t - ft)), 24),
                                  new THREE.MeshBasicMaterial({ color: kind === "broadcast" ? 0x00a000 : 0x9050d0, transparent: true, opacity: 0.6 }));
      ring.position.copy(position(node)); ring.position.z = 0.3;
      world.scene.add(ring); world.radio.push(ring);
      world.broadcastsShown = (world.broadcastsShown || 0) + 1;
    }
    if (peer === null || world.nodes[peer] === undefined) continue;
    if (!tx) links.add(Math.min(node, peer) + "-" + Math.max(node, peer));
    if (tx && t - ft < 0.3 && (kind === "data" || kind === "routing")) {
      const f = (t - ft) / 0.3, a = position(node), b = position(peer);
      const dot = new THREE.Mesh(new THREE.SphereGeometry(world.dotSize, 8, 8),
                                 new THREE.MeshBasicMaterial({ color: kind === "data" ? 0x00a000 : 0x9050d0 }));
      dot.position.set(a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), 0.3);
      world.scene.add(dot); world.radio.push(dot);
    }
  }
  for (const link of links) {
    const [a, b] = link.split("-").map(Number);
    const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints([position(a), position(b)]),
                                new THREE.LineBasicMaterial({ color: 0x80b0ff }));
    world.scene.add(line); world.radio.push(line);
  }
  world.linksUp = links.size;
}

function place(world, t) {
  for (const n of world.nodes) {
    const p = poseAt(n.rows, t) || [t, n.node.x, n.node.y, n.node.theta];
    n.mesh.position.set(p[1], p[2], n.mote ? world.moteLift : 0.1);
    n.mesh.rotation.z = p[3];
    if (n.track) n.track.geometry.setDrawRange(0, n.rows.filter((r) => r[0] <= t).length);
    const last = world.transitions.filter((x) => x[1] === n.node.id && x[0] <= t).pop();
    n.state = last ? last[3] : "";
    n.label.textContent = n.node.name + (n.state ? ` [${n.state}]` : "");
    const level = latest(n.levels, t), death = latest(n.deaths, t);
    paint(n, level ? level[1] : null, Boolean(death && death[2]));
  }
}

function placeLabels(world, camera, element) {
  const w = element.clientWidth, h = element.clientHeight;
  for (const n of world.nodes) {
    const v = n.mesh.position.clone().project(camera);
    const visible = v.z < 1 && Math.abs(v.x) <= 1 && Math.abs(v.y) <= 1 && (!n.mote || world.nodes.length < 60);
    n.label.style.display = visible ? "" : "none";
    n.label.style.left = ((v.x + 1) / 2) * w + "px"; n.label.style.top = ((1 - v.y) / 2) * h + "px";
  }
}

function battery(n) {
  return (n.charge !== null ? `; battery: ${Math.round(100 * n.charge)} %` : "") + (n.dead ? " (dead)" : "");
}

// The robot's latest picture at or before `t` from trace.mcap's compressed camera topic (its
// camera's record_rate), where the run recorded one: the log names robots by their ROS token.
function cameraPanel(world, n, t) {
  const token = (/^[0-9]/.test(n.node.name) ? "_" : "") + n.node.name.replace(/[^A-Za-z0-9_]/g, "_");
  const times = (world.pictures || {})[token];
  if (!times) return "";
  let at = null;
  for (const time of times) if (time <= t + 1e-9) at = time; else break;
  if (at === null) return `<h4>Camera</h4><p id="panel-camera-note">no picture yet</p>`;
  return `<h4>Camera</h4><img id="panel-camera" alt="${n.node.name}'s picture" src="/api/camera?node=${token}&t=${at}">` +
    `<p id="panel-camera-note">taken at ${at.toFixed(2)} s (trace.mcap, at the camera's record rate)</p>`;
}

async function showPanel(world, n, t) {
  // Renders overlap (playback and seek): every render waits for the answer for the latest time
  // asked, and only that answer is kept.
  if (view.routesAt !== Math.round(t)) {
    const asked = (view.routesAt = Math.round(t));
    view.routesAnswer = api(`/api/routes?t=${asked}`).then((routes) => {
      if (view.routesAt === asked) view.routes = routes;
    });
  }
  await view.routesAnswer;
  const name = (id) => (world.nodes[id] ? world.nodes[id].node.name : id);
  const p = n.node.packets || {};
  const sent = world.messages.filter((m) => m[2] === n.node.id && m[0] <= t).length;
  const received = world.messages.filter((m) => m[3] === n.node.id && m[1] !== null && m[1] <= t).length;
  const routes = view.routes.filter((r) => r[0] === n.node.id)
    .map((r) => `<tr><td>${name(r[1])}</td><td>${name(r[2])}</td><td>${r[3]}</td></tr>`).join("");
  const states = world.transitions.filter((x) => x[1] === n.node.id && x[0] <= t)
    .map((x) => `<tr><td>${x[0].toFixed(1)}</td><td>${x[3]}</td><td>${x[4]}</td></tr>`).join("");
  document.getElementById("panel").innerHTML =
    `<h3 id="panel-name">${n.node.name}</h3><p>${n.node.model}; state: ${n.state || "none"}${battery(n)}</p>` +
    `<h4>Packets (whole run)</h4><table id="panel-packets">` +
    ["sent", "received", "forwarded", "dropped"].map((k) => `<tr><th>${k}</th><td data-key="${k}">${p[k] ?? "-"}</td></tr>`).join("") +
    `</table><h4>Messages up to now</h4><p>${sent} sent, ${received} received</p>` +
    `<h4>Routing table</h4><table><tr><th>to</th><th>via</th><th>hops</th></tr>${routes}</table>` +
    `<h4>States</h4><table><tr><th>t</th><th>state</th><th>why</th></tr>${states}</table>` + cameraPanel(world, n, t);
}

// The selected node's routes: a dashed line to the next hop of each destination it has a route to.
function drawRoutes(world, n) {
  const hops = new Set(view.routes.filter((r) => r[0] === n.node.id).map((r) => r[2]));
  for (const hop of hops) {
    if (!world.nodes[hop]) continue;
    const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints([n.mesh.position, world.nodes[hop].mesh.position]),
                                new THREE.LineDashedMaterial({ color: 0x9050d0, dashSize: world.dotSize * 3, gapSize: world.dotSize * 2 }));
    line.computeLineDistances();
    world.scene.add(line); world.radio.push(line);
  }
  world.routesDrawn = hops.size;
}

// The node drawn nearest to a click, within 14 px (motes are small on a large field).
function nearestNode(world, camera, canvas, e) {
  const r = canvas.getBoundingClientRect();
  let best = null, bestDistance = 14;
  for (const n of world.nodes) {
    const v = n.mesh.position.clone().project(camera);
    const d = Math.hypot(((v.x + 1) / 2) * r.width - (e.clientX - r.left), ((1 - v.y) / 2) * r.height - (e.clientY - r.top));
    if (d < bestDistance) { best = n; bestDistance = d; }
  }
  return best;
}

// The view from above zooms with the wheel and pans with the mouse; it does not turn.
function topControls(camera, canvas, box) {
  const controls = new THREE.OrbitControls(camera, canvas);
  controls.enableRotate = false;
  controls.screenSpacePanning = true;
  controls.target.set(box.cx, box.cy, 0);
  camera.lookAt(box.cx, box.cy, 0);
  return controls;
}

// A chart plugin: a line at the time shown.
const timeLine = { id: "timeline", afterDraw(chart) {
  if (!chart.scales.x || chart.config.type === "bar") return;
  const x = chart.scales.x.getPixelForValue(view.t), ctx = chart.ctx;
  ctx.save(); ctx.strokeStyle = "#d04010"; ctx.beginPath();
  ctx.moveTo(x, chart.chartArea.top); ctx.lineTo(x, chart.chartArea.bottom); ctx.stroke(); ctx.restore();
} };

function plots(world, duration) {
  const common = { animation: false, responsive: true, maintainAspectRatio: false, plugins: { legend: { display: false } } };
  const linear = { x: { type: "linear", min: 0, max: duration, title: { display: true, text: "time (s)" } } };
  const delays = world.messages.filter((m) => m[1] !== null).map((m) => ({ x: m[1], y: m[1] - m[0] }));
  const charts = [
    new Chart(document.getElementById("delay"), { type: "scatter", plugins: [timeLine], options: { ...common, scales: linear },
      data: { datasets: [{ data: delays, pointRadius: 2, backgroundColor: "#2060c0" }] } }),
    new Chart(document.getElementById("distance"), { type: "line", plugins: [timeLine], options: { ...common, scales: linear },
      data: { datasets: [{ data: world.distances.map(([x, y]) => ({ x, y })), pointRadius: 0, borderColor: "#d04010" }] } }),
    new Chart(document.getElementById("packets"), { type: "bar", options: common,
      data: { labels: world.nodes.map((n) => n.node.name),
              datasets: [{ data: world.nodes.map((n) => (n.node.packets || {}).received || 0), backgroundColor: "#80b0ff" }] } }),
  ];
  return () => { charts[0].draw(); charts[1].draw(); };
}

// A node as window.sanet.state() gives it: color is its mesh's, as "rrggbb".
function nodeState(n) {
  return { name: n.node.name, model: n.node.model, state: n.state, x: n.mesh.position.x, y: n.mesh.position.y,
           charge: n.charge, dead: n.dead, color: n.mesh.material.color.getHexString() };
}

const legendShown = () => !document.getElementById("legend").hidden;

function makeRenderer(element) {
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  renderer.setSize(element.clientWidth, element.clientHeight);
  element.insertBefore(renderer.domElement, element.firstChild);
  return renderer;
}

// The live view (sanet run/serve --view): frames of poses, states and radio neighbours arrive as
// server-sent events; the latest is drawn.
function live(run) {
  document.getElementById("title").textContent = run.info.name + " (live)";
  for (const id of ["play", "time", "speed", "plots"]) document.getElementById(id).style.display = "none";
  for (const id of ["speed", "ranges"]) document.getElementById(id).parentElement.style.display = "none";
  document.getElementById("panel").innerHTML = "<p>Live: the latest state of the run, as it goes.</p>";
  const element = document.getElementById("world");
  const renderer = makeRenderer(element);
  const box = bounds(run, {});
  // Robots drive beyond where they start: frame the scenario's field (world.size) around them.
  const [wx, wy] = String(run.info.world_size_m || "0 0").split(" ").map(Number);
  box.size = Math.max(box.size * 1.5, wx, wy);
  const world = { ...buildScene(run, {}, box), radio: [], linksUp: 0, moteLift: Math.max(0.05, box.size / 240) };
  const cams = cameras(box, element);
  const controls = new THREE.OrbitControls(cams.perspective, renderer.domElement);
  controls.target.set(box.cx, box.cy, 0);
  const camera = () => (document.getElementById("view").value === "3d" ? cams.perspective : cams.top);
  const state = { t: 0, frames: 0, ended: false };
  const draw = (frame) => {
    frame.poses.forEach(([x, y, theta], id) => {
      const n = world.nodes[id];
      if (!n) return;
      n.mesh.position.set(x, y, n.mote ? world.moteLift : 0.1); n.mesh.rotation.z = theta;
      n.state = frame.states[id] || "";
      n.label.textContent = n.node.name + (n.state ? ` [${n.state}]` : "");
      if (frame.energy) paint(n, frame.energy[id] ?? null, frame.dead.includes(id));
    });
    if (frame.energy) showLegend();
    for (const line of world.radio) world.scene.remove(line);
    world.radio = frame.links.map(([a, b]) => {
      const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints([world.nodes[a].mesh.position, world.nodes[b].mesh.position]),
                                  new THREE.LineBasicMaterial({ color: 0x80b0ff }));
      world.scene.add(line); return line;
    });
    world.linksUp = frame.links.length;
    renderer.render(world.scene, camera());
    placeLabels(world, camera(), element);
    document.getElementById("clock").textContent = `t = ${frame.t.toFixed(1)} s`;
  };
  const events = new EventSource("/api/live");
  events.onmessage = (e) => { const frame = JSON.parse(e.data); state.t = frame.t; state.frames += 1; draw(frame); };
  events.addEventListener("end", () => { state.ended = true; events.close();
    document.getElementById("clock").textContent += " (run ended)"; });
  renderer.domElement.onclick = (e) => {
    const n = nearestNode(world, camera(), renderer.domElement, e);
    if (n) document.getElementById("panel").innerHTML = `<h3 id="panel-name">${n.node.name}</h3><p>${n.node.model}; state: ${n.state || "none"}${battery(n)}</p>`;
  };
  window.sanet = {
    ready: true, live: true,
    state() {
      return { t: state.t, frames: state.frames, ended: state.ended, linksUp: world.linksUp, legend: legendShown(),
               nodes: world.nodes.map(nodeState) };
    },
  };
}

// The time the page opens at: ?t=SECONDS, within the run; a time it cannot show is said on the page.
function startTime(duration) {
  const asked = new URLSearchParams(location.search).get("t");
  if (asked === null) return { t: 0, notice: "" };
  const t = asked.trim() === "" ? NaN : Number(asked);
  if (!Number.isFinite(t)) return { t: 0, notice: `?t=${asked} is not a time in seconds: showing t = 0` };
  if (t < 0) return { t: 0, notice: `?t=${asked} is before the run: showing t = 0` };
  if (t > duration) return { t: duration, notice: `?t=${asked} is past the run's end (${duration} s): showing its end` };
  return { t, notice: "" };
}

function showNotice(text) {
  const notice = document.getElementById("notice");
  notice.textContent = text; notice.hidden = !text;
}

async function main() {
  const run = await api("/api/run");
  if (run.info.live) return live(run);
  const [poses, messages, transitions, distances, energy, metrics, pictures] = await Promise.all(
    [api("/api/poses"), api("/api/messages"), api("/api/transitions"), api("/api/min_distance"), api("/api/energy"),
     api("/api/metrics"), api("/api/cameras").catch(() => ({}))]);
  // The run may have ended before the scenario's duration (an end condition).
  const duration = Number((run.summary && run.summary.simulated_s) || run.info.duration_s);
  document.getElementById("title").textContent = run.info.name;
  if (!distances.length) document.getElementById("distance").parentElement.style.display = "none";
  const element = document.getElementById("world");
  const renderer = makeRenderer(element);
  const box = bounds(run, poses);
  const world = { ...buildScene(run, poses, box), messages, transitions, distances, pictures, radio: [], linksUp: 0,
                  dotSize: Math.max(0.15, box.size / 200), moteLift: Math.max(0.05, box.size / 240) };
  for (const n of world.nodes) {
    n.levels = energy.levels[n.node.id] || [];
    n.deaths = energy.deaths.filter((d) => d[1] === n.node.id);
  }
  if (Object.keys(energy.levels).length) showLegend();
  const cams = cameras(box, element);
  const controls = new THREE.OrbitControls(cams.perspective, renderer.domElement);
  controls.target.set(box.cx, box.cy, 0);
  const zoom = topControls(cams.top, renderer.domElement, box);
  document.getElementById("view").onchange = () => { const top = document.getElementById("view").value === "top";
    controls.enabled = !top; zoom.enabled = top; };
  controls.enabled = false;
  const redrawPlots = plots(world, duration);
  const metricPlots = metricCharts(metrics, duration, timeLine);
  const ranges = radioRanges(world);
  const opening = startTime(duration);
  view.t = opening.t;
  showNotice(opening.notice);
  const slider = document.getElementById("time");
  slider.max = duration;
  const camera = () => (document.getElementById("view").value === "3d" ? cams.perspective : cams.top);
  let plottedAt = null;
  async function render() {
    place(world, view.t);
    drawRadio(world, await frameWindow(view.t), view.t);
    if (view.selected) {
      await showPanel(world, view.selected, view.t);
      drawRoutes(world, view.selected);
    }
    ranges.update(view.selected);
    renderer.render(world.scene, camera());
    placeLabels(world, camera(), element);
    document.getElementById("clock").textContent = `t = ${view.t.toFixed(1)} s`;
    slider.value = view.t;
    if (view.t !== plottedAt) {  // the charts' time line moves only with the time
      plottedAt = view.t;
      redrawPlots();
      metricPlots.redraw();
    }
  }
  let last = performance.now();
  function tick(now) {
    if (view.playing) {
      view.t = Math.min(duration, view.t + ((now - last) / 1000) * Number(document.getElementById("speed").value));
      if (view.t >= duration) view.playing = false;
    }
    playButton.textContent = view.playing ? "Pause" : "Play";
    last = now;
    render().then(() => requestAnimationFrame(tick));
  }
  const playButton = document.getElementById("play");
  playButton.onclick = () => {
    if (!view.playing && view.t >= duration) view.t = 0;  // at the end, play again from the start
    view.playing = !view.playing;
  };
  slider.oninput = () => { view.t = Number(slider.value); };
  renderer.domElement.onclick = (e) => {
    view.selected = nearestNode(world, camera(), renderer.domElement, e);
    if (!view.selected) document.getElementById("panel").innerHTML = "<p>Click a node to see its packets, messages, routes and states.</p>";
  };
  window.sanet = {
    ready: true,
    async seek(t) { view.playing = false; playButton.textContent = "Play"; view.t = Math.max(0, Math.min(duration, t)); await render(); },
    select(name) { view.selected = world.nodes.find((n) => n.node.name === name) || null; return render(); },
    // Resolves once the ranges are measured and drawn (the server measures them as it starts).
    async ranges() { await ranges.answer; await render(); await ranges.settled(); await render(); },
    state() {
      return { t: view.t, duration, playing: view.playing, notice: document.getElementById("notice").textContent,
               linksUp: world.linksUp, routesDrawn: world.routesDrawn || 0, broadcastsShown: world.broadcastsShown || 0,
               motes: world.nodes.filter((n) => n.mote && n.mesh.visible).length, legend: legendShown(),
               nodes: world.nodes.map(nodeState), metrics: metricPlots.state(), ranges: ranges.state() };
    },
  };
  requestAnimationFrame(tick);
}

main().catch((error) => { console.error(error); document.getElementById("panel").textContent = String(error); });

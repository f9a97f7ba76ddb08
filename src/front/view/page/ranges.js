// Each radio's nominal range (/api/radio_ranges): around a node, a circle of the distance at which
// the scenario's link curve (sanet link-curve) crosses a packet reception ratio of 0.5; where the
// world has walls that cost the radio something, the shape the server casts through them
// (/api/radio_range_shape) instead. Which nodes show theirs: #ranges (and ?ranges=): the selected
// node, or every robot while none is; all nodes; none.
"use strict";

const rangeColor = 0x3070d0;

function unitCircle() {
  const points = [];
  for (let i = 0; i < 96; i++) points.push(new THREE.Vector3(Math.cos((2 * Math.PI * i) / 96), Math.sin((2 * Math.PI * i) / 96), 0));
  return new THREE.BufferGeometry().setFromPoints(points);
}

function rangeNote(info) {
  if (info.error) return `no radio ranges: ${info.error}`;
  const radii = info.radios.map((r) => (r.radius_m === null ? `${r.tx_power_dbm} dBm: never half the frames`
    : `${info.radios.length > 1 ? r.tx_power_dbm + " dBm: " : ""}${r.radius_m.toFixed(1)} m ± ${r.precision_m.toFixed(2)} m`));
  return `radio range (half the frames arrive; sanet link-curve, ${info.links} links): ${radii.join("; ")}` +
    (info.walls ? "; shaped by the walls (mean power through them)" : "");
}

// The drawn range's largest and smallest distances from the node: what the page shows, for tests.
function drawnReach(line, centre) {
  const p = line.geometry.attributes.position;
  let radius = 0, shortest = Infinity;
  for (let i = 0; i < p.count; i++) {
    const d = Math.hypot(p.getX(i) * line.scale.x + line.position.x - centre.x, p.getY(i) * line.scale.y + line.position.y - centre.y);
    radius = Math.max(radius, d); shortest = Math.min(shortest, d);
  }
  return { radius, shortest };
}

function radioRanges(world) {
  const select = document.getElementById("ranges");
  const asked = new URLSearchParams(location.search).get("ranges");
  if (["auto", "all", "none"].includes(asked)) select.value = asked;
  const ranges = { info: null, lines: new Map(), shapes: new Map() };
  const radioOf = (n) => (ranges.info && ranges.info.radios ? ranges.info.radios.findIndex((r) => r.nodes.includes(n.node.id)) : -1);
  const wanted = (n, selected) => select.value === "all" || (select.value === "auto" && (selected ? n === selected : !n.mote));
  // Through walls the shape depends on where the node is: asked again once it has moved.
  function shape(n, radio, line) {
    const p = n.mesh.position, last = ranges.shapes.get(n);
    const far = Math.max(0.5, ranges.info.radios[radio].radius_m / 100);
    if (last && (last.pending || Math.hypot(last.x - p.x, last.y - p.y) < far)) return;
    const at = { x: p.x, y: p.y, pending: true };
    ranges.shapes.set(n, at);
    at.answer = api(`/api/radio_range_shape?radio=${radio}&x=${p.x}&y=${p.y}`).then((points) => {
      line.geometry.dispose();
      line.geometry = new THREE.BufferGeometry().setFromPoints(points.map(([x, y]) => new THREE.Vector3(x, y, 0.25)));
      line.userData.shaped = true;
    }).catch((e) => {  // said on the page; asked again when the node next moves
      document.getElementById("ranges-note").textContent = `radio range through the walls: ${e.message || e}`;
    }).finally(() => { at.pending = false; });
  }
  function lineOf(n, radio) {
    if (!ranges.lines.has(n)) {
      const line = new THREE.LineLoop(unitCircle(), new THREE.LineBasicMaterial({ color: rangeColor, transparent: true, opacity: 0.6 }));
      if (!ranges.info.walls) line.scale.setScalar(ranges.info.radios[radio].radius_m);
      world.scene.add(line); ranges.lines.set(n, line);
    }
    return ranges.lines.get(n);
  }
  return {
    answer: api("/api/radio_ranges").then((info) => {
      ranges.info = info;
      document.getElementById("ranges-note").textContent = rangeNote(info);
    }),
    // Shows the ranges wanted at the nodes' drawn positions.
    update(selected) {
      if (!ranges.info || !ranges.info.radios) return;
      for (const n of world.nodes) {
        const radio = radioOf(n), show = radio >= 0 && ranges.info.radios[radio].radius_m !== null && wanted(n, selected);
        if (!show) { if (ranges.lines.has(n)) ranges.lines.get(n).visible = false; continue; }
        const line = lineOf(n, radio);
        if (ranges.info.walls) shape(n, radio, line);
        else line.position.set(n.mesh.position.x, n.mesh.position.y, 0.25);
        // Through walls, hidden until its first shape arrives (not a unit circle at the origin).
        line.visible = !ranges.info.walls || Boolean(line.userData.shaped);
      }
    },
    // Waits for the shapes asked for (through walls) to arrive.
    settled() { return Promise.all([...ranges.shapes.values()].map((s) => s.answer)); },
    state() {
      const info = ranges.info || {};
      const drawn = [...ranges.lines].filter(([, line]) => line.visible)
        .map(([n, line]) => ({ name: n.node.name, ...drawnReach(line, n.mesh.position) }));
      return { mode: select.value, error: info.error || null, walls: Boolean(info.walls), drawn,
               radios: (info.radios || []).map((r) => ({ txPower: r.tx_power_dbm, radius: r.radius_m, precision: r.precision_m,
                                                         nodes: r.nodes.map((id) => world.nodes[id].node.name) })) };
    },
  };
}

// The controllers' metrics (metrics.csv, Node::Metric, served as /api/metrics): one chart per
// metric name under the map, a line per node; a metric more than `metricNodesApart` nodes report
// is folded into the mean of the values reported in each slice of time (a hundredth of the run, or
// the nodes' typical interval between reports if longer), and its chart says so; a metric of
// events (every value the same) is drawn as running totals.
"use strict";

const metricNodesApart = 8;
const metricColors = ["#2060c0", "#d04010", "#20a040", "#9050d0", "#c09000", "#00a0b0", "#e060a0", "#606060"];

// The slice of time the mean is taken over: a hundredth of the run, or longer when the nodes
// report less often (the median of their mean intervals), so that each slice holds every node's.
function foldWidth(byNode, duration) {
  const intervals = Object.values(byNode).filter((rows) => rows.length > 1)
    .map((rows) => (rows[rows.length - 1][0] - rows[0][0]) / (rows.length - 1)).sort((a, b) => a - b);
  const typical = intervals.length ? intervals[Math.floor(intervals.length / 2)] : 0;
  return Math.max(duration / 100, typical, 1e-9);
}

// The mean of the values every node reported in each slice of `width` seconds.
function foldedMean(byNode, width) {
  const sums = new Map(), counts = new Map();
  for (const rows of Object.values(byNode))
    for (const [t, v] of rows) {
      const i = Math.floor(t / width);
      sums.set(i, (sums.get(i) || 0) + v); counts.set(i, (counts.get(i) || 0) + 1);
    }
  return [...sums.keys()].sort((a, b) => a - b).map((i) => ({ x: (i + 0.5) * width, y: sums.get(i) / counts.get(i) }));
}

// Running totals of rows [[t, v], ...] in time order: [{x: t, y: total so far}].
function runningTotal(rows) {
  let total = 0;
  return [...rows].sort((a, b) => a[0] - b[0]).map(([x, v]) => ({ x, y: (total += v) }));
}

// A metric whose every value is the same (Metric("delivered", 1) per event) says nothing as values:
// it is drawn as running totals, per node, or over all nodes past `metricNodesApart`.
function eventSeries(name, byNode, value) {
  const nodes = Object.keys(byNode);
  const color = (i) => metricColors[i % metricColors.length];
  const caption = `${name}: running total (every value is ${value}: a count of events)`;
  if (nodes.length > metricNodesApart)
    return { folded: true, cumulative: true, nodes, caption: `${caption}, over the ${nodes.length} nodes`,
             datasets: [{ label: `${nodes.length} nodes`, data: runningTotal(Object.values(byNode).flat()), borderColor: color(0), backgroundColor: color(0) }] };
  return { folded: false, cumulative: true, nodes, caption,
           datasets: nodes.map((node, i) => ({ label: node, data: runningTotal(byNode[node]), borderColor: color(i), backgroundColor: color(i) })) };
}

// The datasets of one metric, and what the chart says about them.
function metricSeries(name, byNode, duration) {
  const nodes = Object.keys(byNode);
  const values = Object.values(byNode).flat().map(([, v]) => v);
  if (values.length > 1 && values.every((v) => v === values[0])) return eventSeries(name, byNode, values[0]);
  if (nodes.length > metricNodesApart) {
    const width = foldWidth(byNode, duration);
    const data = foldedMean(byNode, width);
    return { folded: true, nodes, caption: `${name}: mean over the ${nodes.length} nodes reporting it, per ${width.toPrecision(3)} s`,
             datasets: [{ label: `mean of ${nodes.length} nodes`, data, borderColor: metricColors[0], backgroundColor: metricColors[0] }] };
  }
  const datasets = nodes.map((node, i) => ({ label: node, data: byNode[node].map(([x, y]) => ({ x, y })),
                                            borderColor: metricColors[i % metricColors.length],
                                            backgroundColor: metricColors[i % metricColors.length] }));
  return { folded: false, nodes, caption: `${name} (metrics.csv) over time (s)`, datasets };
}

// Draws a chart per metric into #metrics; returns {redraw(), state()}.
function metricCharts(metrics, duration, timeLine) {
  const section = document.getElementById("metrics");
  const shown = [];
  for (const [name, byNode] of Object.entries(metrics)) {
    const series = metricSeries(name, byNode, duration);
    const figure = document.createElement("figure");
    figure.dataset.metric = name;
    figure.innerHTML = `<figcaption></figcaption><canvas></canvas>`;
    figure.firstChild.textContent = series.caption;
    section.appendChild(figure);
    const chart = new Chart(figure.lastChild, { type: "scatter", plugins: [timeLine],
      data: { datasets: series.datasets.map((d) => ({ ...d, showLine: true, pointRadius: 2, borderWidth: 1 })) },
      options: { animation: false, responsive: true, maintainAspectRatio: false,
                 plugins: { legend: { display: series.datasets.length > 1, labels: { boxWidth: 10 } } },
                 scales: { x: { type: "linear", min: 0, max: duration, title: { display: true, text: "time (s)" } } } } });
    const first = series.datasets[0].data;
    shown.push({ name, chart, nodes: series.nodes, folded: series.folded, cumulative: Boolean(series.cumulative),
                 last: first.length ? first[first.length - 1].y : null,
                 points: series.datasets.reduce((n, d) => n + d.data.length, 0) });
  }
  section.hidden = shown.length === 0;
  return {
    redraw() { for (const m of shown) m.chart.draw(); },
    state() { return shown.map(({ name, nodes, folded, cumulative, last, points }) => ({ name, nodes, folded, cumulative, last, points })); },
  };
}

// The controllers' metrics (metrics.csv, Node::Metric, served as /api/metrics): one chart per
// metric name under the map, a line per node; a metric more than `metricNodesApart` nodes report
// is folded into the mean of the values reported in each slice of time (a hundredth of the run, or
// the nodes' typical interval between reports if longer), and its chart says so.
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

// The datasets of one metric, and what the chart says about them.
function metricSeries(name, byNode, duration) {
  const nodes = Object.keys(byNode);
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
    shown.push({ name, chart, nodes: series.nodes, folded: series.folded,
                 points: series.datasets.reduce((n, d) => n + d.data.length, 0) });
  }
  section.hidden = shown.length === 0;
  return {
    redraw() { for (const m of shown) m.chart.draw(); },
    state() { return shown.map(({ name, nodes, folded, points }) => ({ name, nodes, folded, points })); },
  };
}

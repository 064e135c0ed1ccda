// geardyn 3-D view, the side panel: the mode list (number, frequency [Hz], type, the largest
// strain-energy fractions) and the Campbell diagram (campbell.csv: the modes' frequencies
// against the input speed, the order lines dashed), linked: a click on a row or on a mode's
// curve animates that mode, and the animated mode's row and curve are highlighted.
// window.geardynViewPanel.build(root, side, data, onSelect, onOds) -> {highlight(mode, ods)}; el and fmt, the
// element and number helpers view3d.js shares.
window.geardynViewPanel = (function () {
  'use strict';
  var SVG = 'http://www.w3.org/2000/svg';

  function el(tag, cls, parent, text) {
    var e = document.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined) e.textContent = text;
    if (parent) parent.appendChild(e);
    return e;
  }
  function svg(tag, attrs, parent) {
    var e = document.createElementNS(SVG, tag);
    Object.keys(attrs).forEach(function (k) { e.setAttribute(k, attrs[k]); });
    if (parent) parent.appendChild(e);
    return e;
  }
  function fmt(v, digits) {  // significant digits, no exponent below 1e6, no trailing zeros
    var s = Number(v).toPrecision(digits || 4);
    if (s.indexOf('e') >= 0) s = String(Number(s));
    return s.indexOf('.') >= 0 ? s.replace(/\.?0+$/, '') : s;
  }
  // About five round ticks over [0, top].
  function ticks(top) {
    var raw = top / 5, p = Math.pow(10, Math.floor(Math.log10(raw))), n = raw / p;
    var step = (n < 1.5 ? 1 : n < 3.5 ? 2 : n < 7.5 ? 5 : 10) * p, out = [];
    for (var k = 0; k * step <= top * 1.0001; ++k) out.push(k * step);
    return out;
  }

  function modeList(side, data, onSelect) {
    el('div', 'gd-v3-heading', side, 'Modes (click to animate)');
    var scroller = el('div', 'gd-v3-list', side), table = el('table', null, scroller);
    var head = el('tr', null, el('thead', null, table));
    ['#', 'f [Hz]', 'type', 'strain energy [%]'].forEach(function (h) { el('th', null, head, h); });
    var tbody = el('tbody', null, table), rows = [];
    data.modes.forEach(function (m, i) {
      var tr = el('tr', 'gd-v3-mode', tbody);
      tr.setAttribute('data-mode', String(i));
      el('td', null, tr, String(m.mode));
      el('td', 'num', tr, fmt(m.frequency_hz, 5));
      el('td', null, tr, m.type);
      el('td', 'energy', tr, m.energy.map(function (e) { return e[0] + ' ' + fmt(100 * e[1], 2); }).join(', '));
      tr.title = 'mode ' + m.mode + ', ζ = ' + fmt(100 * m.damping_ratio, 3) + ' %' + (m.kinetic ?
        '; kinetic energy: ' + Object.keys(m.kinetic).map(function (k) { return k + ' ' + fmt(100 * m.kinetic[k], 2) + ' %'; }).join(', ') : '');
      tr.onclick = function () { onSelect(i); };
      rows.push(tr);
    });
    return rows;
  }

  function campbell(side, data, onSelect) {
    var c = data.campbell;
    if (!c || !c.modes_hz.length) return null;
    el('div', 'gd-v3-heading', side, 'Campbell diagram (click a mode)');
    var W = 310, H = 210, L = 46, R = 18, T = 8, B = 34;
    var box = svg('svg', {width: W, height: H, viewBox: '0 0 ' + W + ' ' + H, 'class': 'gd-v3-campbell'}, side);
    var smax = Math.max.apply(null, c.speed_rpm), fmax = 0;
    c.modes_hz.forEach(function (m) { fmax = Math.max(fmax, Math.max.apply(null, m)); });
    fmax *= 1.08;
    function X(s) { return L + (W - L - R) * s / smax; }
    function Y(f) { return H - B - (H - B - T) * f / fmax; }
    ticks(smax).forEach(function (t) {
      svg('line', {x1: X(t), x2: X(t), y1: T, y2: H - B, stroke: '#e3e6ea'}, box);
      svg('text', {x: X(t), y: H - B + 13, 'text-anchor': 'middle', 'class': 'tick'}, box).textContent = fmt(t, 4);
    });
    ticks(fmax).forEach(function (t) {
      svg('line', {x1: L, x2: W - R, y1: Y(t), y2: Y(t), stroke: '#e3e6ea'}, box);
      svg('text', {x: L - 4, y: Y(t) + 3, 'text-anchor': 'end', 'class': 'tick'}, box).textContent = fmt(t, 4);
    });
    svg('text', {x: (L + W - R) / 2, y: H - 4, 'text-anchor': 'middle', 'class': 'label'}, box).textContent = 'input speed [rpm]';
    svg('text', {x: 11, y: (T + H - B) / 2, 'text-anchor': 'middle', 'class': 'label',
                 transform: 'rotate(-90 11 ' + (T + H - B) / 2 + ')'}, box).textContent = 'frequency [Hz]';
    var clip = 'gd-clip-' + Math.random().toString(36).slice(2);
    svg('rect', {x: L, y: T, width: W - L - R, height: H - B - T}, svg('clipPath', {id: clip}, box));
    var plot = svg('g', {'clip-path': 'url(#' + clip + ')'}, box);
    c.orders.forEach(function (o) {
      svg('line', {x1: X(0), y1: Y(0), x2: X(smax), y2: Y(o.order * smax / 60), stroke: '#7fa7d1',
                   'stroke-dasharray': '4 3', 'stroke-width': 1}, plot).appendChild(
        svg('title', {}, null)).textContent = o.name + ' (order ' + fmt(o.order, 4) + ')';
    });
    if (data.speed_rpm) {
      svg('line', {x1: X(data.speed_rpm), x2: X(data.speed_rpm), y1: T, y2: H - B, stroke: '#888',
                   'stroke-dasharray': '2 2'}, plot);
    }
    // Curve k is the k-th lowest tracked frequency at each speed: it belongs to the mode whose
    // frequency is nearest its value at the modal analysis's speed (linear interpolation).
    function modeOf(m) {
      var s = data.speed_rpm || 0, k = 1;
      while (k < c.speed_rpm.length - 1 && c.speed_rpm[k] < s) ++k;
      var s0 = c.speed_rpm[k - 1], s1 = c.speed_rpm[k], w = s1 > s0 ? Math.min(Math.max((s - s0) / (s1 - s0), 0), 1) : 0;
      var f = (1 - w) * m[k - 1] + w * m[k], best = 0;
      data.modes.forEach(function (mode, j) {
        if (Math.abs(mode.frequency_hz - f) < Math.abs(data.modes[best].frequency_hz - f)) best = j;
      });
      return best;
    }
    var curves = c.modes_hz.map(function (m) {
      var i = modeOf(m);
      var d = m.map(function (f, k) { return (k ? 'L' : 'M') + X(c.speed_rpm[k]).toFixed(1) + ' ' + Y(f).toFixed(1); }).join('');
      var hit = svg('path', {d: d, stroke: 'transparent', 'stroke-width': 8, fill: 'none', 'class': 'hit'}, plot);
      var path = svg('path', {d: d, stroke: '#6b7280', 'stroke-width': 1.2, fill: 'none'}, plot);
      [hit, path].forEach(function (p) {
        p.style.cursor = 'pointer';
        p.addEventListener('click', function () { onSelect(i); });
        svg('title', {}, p).textContent = 'mode ' + data.modes[i].mode;
      });
      path.gdMode = i;
      return path;
    });
    svg('rect', {x: L, y: T, width: W - L - R, height: H - B - T, fill: 'none', stroke: '#555'}, box);
    // The shown operating deflection shape: its speed and frequency.
    var dot = svg('circle', {r: 4.5, fill: '#d62728', stroke: '#fff', 'stroke-width': 1.5, visibility: 'hidden'}, plot);
    curves.mark = function (o) {
      dot.setAttribute('visibility', o ? 'visible' : 'hidden');
      if (o) { dot.setAttribute('cx', X(o.speed_rpm)); dot.setAttribute('cy', Y(o.frequency_hz)); }
    };
    return curves;
  }

  // The operating deflection shapes: one choice per speed, mesh and order.
  function odsChoice(side, data, onOds) {
    if (!data.ods || !data.ods.length) return null;
    var row = el('div', 'gd-v3-ods', side);
    el('label', null, row, 'Operating deflection shape (forced response)');
    var select = el('select', null, row);
    el('option', null, select, '(modes)').value = '-1';
    data.ods.forEach(function (o, j) {
      var option = el('option', null, select, fmt(o.speed_rpm, 5) + ' rpm · ' + o.mesh + ' ×' + o.order +
                      ' · ' + fmt(o.frequency_hz, 4) + ' Hz');
      option.value = String(j);
    });
    select.onchange = function () { if (Number(select.value) >= 0) onOds(Number(select.value)); };
    return select;
  }

  function build(root, side, data, onSelect, onOds) {
    var rows = modeList(side, data, onSelect), ods = odsChoice(side, data, onOds);
    var curves = campbell(side, data, onSelect) || [];
    return {
      highlight: function (i, j) {
        if (ods) ods.value = String(j);
        if (curves.mark) curves.mark(j >= 0 ? data.ods[j] : null);
        rows.forEach(function (r, k) { r.classList.toggle('selected', k === i); });
        if (rows[i]) rows[i].scrollIntoView({block: 'nearest'});
        curves.forEach(function (p) {
          p.setAttribute('stroke', p.gdMode === i ? '#d62728' : '#6b7280');
          p.setAttribute('stroke-width', p.gdMode === i ? 2.6 : 1.2);
          if (p.gdMode === i) p.parentNode.appendChild(p);
        });
      }
    };
  }
  return {build: build, el: el, fmt: fmt};
})();

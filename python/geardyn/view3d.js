// geardyn 3-D view of a gear train (python/geardyn/view3d.py writes its data): the scene
// (view3d_scene.js, view3d_parts.js), the mode list and Campbell diagram (view3d_panel.js), a
// legend, an axis triad and the scale of the drawn motion. A mode animates as
// q(t) = Re(φ e^{iωt}) (φ: the complex mode shape of mode_shapes.csv, or an operating
// deflection shape of forced_ods.csv), scaled so the largest displacement is the amplitude
// slider's share of the train's size.
window.geardynView3d = (function () {
  'use strict';
  var PERIOD_S = 1.6;  // one drawn cycle [s]

  var el = window.geardynViewPanel.el, fmt = window.geardynViewPanel.fmt;

  // The header (title, play, amplitude, outline) and the body (side panel, canvas with its
  // note, tooltip, legend and axis triad) of a view.
  function layout(root) {
    root.innerHTML = '';
    var head = el('div', 'gd-v3-head', root), out = {title: el('div', 'gd-v3-title', head)};
    var controls = el('div', 'gd-v3-controls', head);
    out.play = el('button', 'gd-v3-play', controls, 'pause');
    el('label', null, controls, 'amplitude');
    out.amp = el('input', null, controls); out.amp.type = 'range'; out.amp.min = 1; out.amp.max = 20; out.amp.value = 6;
    out.ghost = el('input', null, controls); out.ghost.type = 'checkbox'; out.ghost.checked = true;
    el('label', null, controls, 'undeformed outline');
    var body = el('div', 'gd-v3-body', root);
    out.side = el('div', 'gd-v3-side', body);
    out.wrap = el('div', 'gd-v3-canvas', body);
    out.note = el('div', 'gd-v3-note', out.wrap);
    out.tip = el('div', 'gd-v3-tip', out.wrap);
    out.legend = el('div', 'gd-v3-legend', out.wrap);
    out.triad = el('canvas', 'gd-v3-triad', out.wrap); out.triad.width = 90; out.triad.height = 90;
    return out;
  }

  function legend(box, kinds) {
    window.geardynParts.LEGEND.forEach(function (item) {
      if (!kinds[item[0]]) return;
      var row = el('div', null, box), sw = el('span', 'gd-v3-swatch', row);
      sw.style.background = '#' + item[2].toString(16).padStart(6, '0');
      el('span', null, row, item[1]);
    });
  }

  function mount(root, data, lib) {
    var t0 = performance.now(), times = {}, ui = layout(root);
    var view = window.geardynScene.create(lib, ui.wrap, data), extent = view.extent;
    legend(ui.legend, view.kinds);
    view.hover(ui.tip);
    times.parts = performance.now() - t0;
    var state = {mode: 0, ods: -1, shape: data.modes[0], phase: 0, playing: true, start: performance.now()};
    var disp = new Float64Array(6 * data.bodies.length);
    function render() {
      if (state.playing) state.phase = 2 * Math.PI * ((performance.now() - state.start) / 1000 / PERIOD_S % 1);
      var m = state.shape, c = Math.cos(state.phase), s = Math.sin(state.phase);
      var scale = (ui.amp.value / 100) * extent;
      for (var i = 0; i < disp.length; ++i) disp[i] = scale * (m.re[i] * c - m.im[i] * s);
      view.place(disp);
      view.render();
      view.drawTriad(ui.triad);
    }
    // At most FPS frames a second: the view stays light on a machine drawing WebGL in software.
    // Paused, it draws only when something changed (a mode, the amplitude, the camera, the size).
    var FPS = 24, last = 0, dirty = true;
    function invalidate() { dirty = true; }
    function frame(now) {
      if (now - last >= 1000 / FPS && (state.playing || dirty)) {
        last = now; dirty = false; render(); root.gdFrame = (root.gdFrame || 0) + 1;
      }
      requestAnimationFrame(frame);
    }
    view.onCameraChange(invalidate);

    var panel = window.geardynViewPanel.build(root, ui.side, data, select, selectOds);
    function scaleNote(what) {
      ui.note.textContent = 'motion scaled: ' + what + ' drawn as ' + ui.amp.value + ' % of the train\'s size (' +
                            fmt(1e3 * extent, 3) + ' mm); rotations as displacement at the part\'s radius';
    }
    function title(bold, rest, frequency) {
      ui.title.innerHTML = '';
      el('b', null, ui.title, bold);
      el('span', null, ui.title, rest);
      ui.title.setAttribute('data-frequency-hz', String(frequency));
    }
    function select(i) {
      var m = data.modes[i];
      state.mode = i; state.ods = -1; state.shape = m;
      title('Mode ' + m.mode + ': ' + fmt(m.frequency_hz, 5) + ' Hz', ' · ' + m.type + ' · ζ = ' +
            fmt(100 * m.damping_ratio, 3) + ' %' + (data.speed_rpm ? ' · at ' + fmt(data.speed_rpm, 5) + ' rpm' : ''),
            m.frequency_hz);
      panel.highlight(i, -1);
      scaleNote('largest displacement');
      invalidate();
    }
    // An operating deflection shape of the forced response (forced_ods.csv): its amplitudes
    // are physical, the largest is named in the title.
    function selectOds(j) {
      var o = data.ods[j];
      state.ods = j; state.shape = o;
      title('ODS at ' + fmt(o.speed_rpm, 5) + ' rpm, ' + o.mesh + ' order ' + o.order + ': ' + fmt(o.frequency_hz, 5) + ' Hz',
            ' · largest amplitude ' + fmt(1e6 * o.largest_m, 3) + ' µm', o.frequency_hz);
      panel.highlight(-1, j);
      scaleNote('largest amplitude (' + fmt(1e6 * o.largest_m, 3) + ' µm)');
      invalidate();
    }
    ui.play.onclick = function () {
      state.playing = !state.playing; ui.play.textContent = state.playing ? 'pause' : 'play';
      state.start = performance.now() - state.phase / (2 * Math.PI) * PERIOD_S * 1000;
    };
    ui.amp.oninput = function () { if (state.ods >= 0) selectOds(state.ods); else select(state.mode); };
    ui.ghost.onchange = function () { view.ghost.visible = ui.ghost.checked; invalidate(); };
    window.addEventListener('resize', function () { view.resize(); invalidate(); });
    view.resize(); times.placed = performance.now() - t0;
    select(0);
    root.gdView = {
      select: select, selectOds: selectOds, modes: data.modes.length,
      setPlaying: function (on) { if (on !== state.playing) ui.play.onclick(); },
      setPhase: function (p) { state.phase = p; render(); }
    };
    render(); times.first = performance.now() - t0;
    root.setAttribute('data-times', JSON.stringify(times));
    root.setAttribute('data-rendered-ms', String(performance.now()));
    root.setAttribute('data-rendered', '1');
    // The undeformed outline and the animation start together, after the page's figures (a
    // report sets window.geardynView3dWait): the first frame is drawn without the outline.
    var started = false;
    root.gdStart = function () {
      if (started) return;
      started = true;
      view.snapshotGhost();
      state.start = performance.now();
      requestAnimationFrame(frame);
    };
    if (!window.geardynView3dWait) setTimeout(root.gdStart, 0);
  }

  // Resolved when every view on the page has drawn its first frame (or failed).
  var mountedResolve, mounted = new Promise(function (resolve) { mountedResolve = resolve; });
  function mountAll() {
    var views = Array.prototype.slice.call(document.querySelectorAll('.gd-view3d'));
    if (!views.length) { mountedResolve(); return; }
    window.gdLib.three().then(function (lib) {
      views.forEach(function (root) {
        if (root.gdView) return;
        try {
          mount(root, JSON.parse(document.getElementById(root.id + '-data').textContent), lib);
        } catch (error) {
          root.textContent = '3-D view: ' + error;
          root.setAttribute('data-rendered', 'error');
          console.error(error);
        }
      });
    }).catch(function (error) { console.error(error); }).then(function () {
      setTimeout(mountedResolve, 0);
    });
  }
  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', mountAll);
  else mountAll();
  // Starts the animations (a page that set window.geardynView3dWait calls it when it is ready).
  function play() {
    document.querySelectorAll('.gd-view3d').forEach(function (root) { if (root.gdStart) root.gdStart(); });
  }
  return {mount: mount, mountAll: mountAll, mounted: mounted, play: play};
})();

// geardyn 3-D view of a gear train (python/geardyn/view3d.py writes its data): the parts
// (view3d_parts.js) on their bodies, a mode list where a click animates the mode, the Campbell
// diagram linked to the list, a legend, an axis triad and the scale of the drawn motion.
// A mode animates as q(t) = Re(φ e^{iωt}) (φ: the complex mode shape of mode_shapes.csv), each
// body moved by its translations (x, y, z) and turned by its rotations (θ, θ_y, θ_z), scaled
// so the largest displacement is `amplitude` of the train's size; the flexible shafts bend
// between their nodes by the beam's cubic (Hermite) shape functions (Przemieniecki 1968,
// eq. 5.104: v = N1 v_a + N2 L θ_z,a + N3 v_b + N4 L θ_z,b, w with −θ_y).
window.geardynView3d = (function () {
  'use strict';
  var PERIOD_S = 1.6;  // one drawn cycle [s]

  var el = window.geardynViewPanel.el, fmt = window.geardynViewPanel.fmt;

  function mount(root, data, lib) {
    var THREE = lib.THREE, Parts = window.geardynParts, t0 = performance.now(), times = {};
    root.innerHTML = '';
    var head = el('div', 'gd-v3-head', root), titleEl = el('div', 'gd-v3-title', head);
    var controls = el('div', 'gd-v3-controls', head);
    var play = el('button', 'gd-v3-play', controls, 'pause');
    el('label', null, controls, 'amplitude');
    var amp = el('input', null, controls); amp.type = 'range'; amp.min = 1; amp.max = 20; amp.value = 6;
    var ghostBox = el('input', null, controls); ghostBox.type = 'checkbox'; ghostBox.checked = true;
    el('label', null, controls, 'undeformed outline');
    var body = el('div', 'gd-v3-body', root), side = el('div', 'gd-v3-side', body);
    var wrap = el('div', 'gd-v3-canvas', body);
    var note = el('div', 'gd-v3-note', wrap), tip = el('div', 'gd-v3-tip', wrap);
    var legend = el('div', 'gd-v3-legend', wrap);
    var triad = el('canvas', 'gd-v3-triad', wrap); triad.width = 90; triad.height = 90;

    var renderer = new THREE.WebGLRenderer({antialias: true});
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    wrap.insertBefore(renderer.domElement, note);
    var scene = new THREE.Scene();
    scene.background = new THREE.Color(0xf3f5f7);
    scene.add(new THREE.HemisphereLight(0xffffff, 0x7d8894, 1.6));
    var key = new THREE.DirectionalLight(0xffffff, 2.2), fill = new THREE.DirectionalLight(0xffffff, 0.8);
    scene.add(key); scene.add(fill);
    var world = new THREE.Group();
    world.rotation.x = -Math.PI / 2;  // the train's z up
    scene.add(world);

    var built = Parts.build(THREE, data), bodies = data.bodies, nodes = [];
    Parts.LEGEND.forEach(function (item) {
      if (!built.kinds[item[0]]) return;
      var row = el('div', null, legend), sw = el('span', 'gd-v3-swatch', row);
      sw.style.background = '#' + item[2].toString(16).padStart(6, '0');
      el('span', null, row, item[1]);
    });
    bodies.forEach(function (b) {
      var n = new THREE.Group();
      n.position.set(b.c[0], b.c[1], b.c[2]);
      world.add(n); nodes.push(n);
    });
    built.parts.forEach(function (p) { nodes[p.body].add(p.object); });
    times.parts = performance.now() - t0;
    var SUB = 4, unit = new THREE.CylinderGeometry(1, 1, 1, 40, 1, false);
    var shaftMaterial = Parts.material(THREE, Parts.COLOURS.shaft);
    var segments = [];
    built.elements.forEach(function (e) {
      for (var k = 0; k < SUB; ++k) {
        var m = new THREE.Mesh(unit, shaftMaterial);
        world.add(m); segments.push({mesh: m, e: e, k: k});
      }
    });
    var ghostLines = new THREE.Group();
    scene.add(ghostLines);

    var state = {mode: 0, ods: -1, shape: data.modes[0], phase: 0, playing: true, start: performance.now()};
    var v = new THREE.Vector3(), q = new THREE.Quaternion(), axis = new THREE.Vector3();
    var disp = new Float64Array(6 * bodies.length);
    shapeAtRest();
    // The train's size from its parts at rest (the shaft segments placed).
    var box = new THREE.Box3().setFromObject(world), size = box.getSize(new THREE.Vector3());
    var extent = Math.max(size.x, size.y, size.z, 1e-3);
    var camera = new THREE.PerspectiveCamera(35, 1, extent / 100, extent * 100);
    var centre = box.getCenter(new THREE.Vector3());
    // A train long along its shafts is seen from the side and above; a flat one (a planetary
    // stage) obliquely from its axis.
    var view = size.x > 0.6 * Math.max(size.y, size.z) ? [0.4, 0.85, 1.55] : [1.25, 0.8, 1.5];
    camera.position.set(centre.x + view[0] * extent, centre.y + view[1] * extent, centre.z + view[2] * extent);
    key.position.set(1.5 * extent, 3 * extent, 2 * extent);
    fill.position.set(-2 * extent, 0.5 * extent, -1.5 * extent);
    var orbit = new lib.OrbitControls(camera, renderer.domElement);
    orbit.target.copy(centre); orbit.enableDamping = false; orbit.update();

    // The undeformed train in grey: the pitch circles and the shafts' axes at rest.
    function snapshotGhost() {
      shapeAtRest();
      world.updateMatrixWorld(true);
      var mat = new THREE.LineBasicMaterial({color: 0x9aa3ad});
      world.traverse(function (o) {
        if (o.type === 'Line') {
          var line = new THREE.Line(o.geometry, mat);
          line.applyMatrix4(o.matrixWorld);
          ghostLines.add(line);
        }
      });
      data.geometry.shafts.forEach(function (s) {
        var pts = s.bodies.map(function (n) {
          var c = bodies[built.index[n]].c;
          return new THREE.Vector3(c[0], c[1], c[2]).applyMatrix4(world.matrixWorld);
        });
        if (pts.length > 1) ghostLines.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(pts), mat));
      });
    }

    function shapeAt(phase) {
      var m = state.shape, c = Math.cos(phase), s = Math.sin(phase);
      var scale = (amp.value / 100) * extent;
      for (var i = 0; i < disp.length; ++i) disp[i] = scale * (m.re[i] * c - m.im[i] * s);
    }
    function place() {
      bodies.forEach(function (b, i) {
        var d = disp.subarray(6 * i, 6 * i + 6);
        nodes[i].position.set(b.c[0] + d[0], b.c[1] + d[1], b.c[2] + d[2]);
        var angle = Math.hypot(d[3], d[4], d[5]);
        if (angle > 1e-12) nodes[i].quaternion.setFromAxisAngle(axis.set(d[3], d[4], d[5]).divideScalar(angle), angle);
        else nodes[i].quaternion.identity();
      });
      segments.forEach(function (s) {
        var a = bodies[s.e.a].c, b = bodies[s.e.b].c, L = b[0] - a[0];
        var da = disp.subarray(6 * s.e.a, 6 * s.e.a + 6), db = disp.subarray(6 * s.e.b, 6 * s.e.b + 6);
        var p0 = hermite(a, b, da, db, L, s.k / SUB), p1 = hermite(a, b, da, db, L, (s.k + 1) / SUB);
        v.set(p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]);
        var len = v.length();
        s.mesh.position.set(0.5 * (p0[0] + p1[0]), 0.5 * (p0[1] + p1[1]), 0.5 * (p0[2] + p1[2]));
        s.mesh.quaternion.setFromUnitVectors(axis.set(0, 1, 0), v.divideScalar(len || 1));
        s.mesh.scale.set(s.e.radius, len, s.e.radius);
      });
    }
    function shapeAtRest() { disp.fill(0); place(); }
    function hermite(a, b, da, db, L, xi) {
      var xi2 = xi * xi, xi3 = xi2 * xi;
      var n1 = 1 - 3 * xi2 + 2 * xi3, n2 = L * (xi - 2 * xi2 + xi3), n3 = 3 * xi2 - 2 * xi3, n4 = L * (xi3 - xi2);
      return [a[0] + xi * L + (1 - xi) * da[0] + xi * db[0],
              a[1] + xi * (b[1] - a[1]) + n1 * da[1] + n2 * da[5] + n3 * db[1] + n4 * db[5],
              a[2] + xi * (b[2] - a[2]) + n1 * da[2] - n2 * da[4] + n3 * db[2] - n4 * db[4]];
    }

    function resize() {
      var w = wrap.clientWidth || 800, h = wrap.clientHeight || 520;
      renderer.setSize(w, h, true);
      camera.aspect = w / h; camera.updateProjectionMatrix();
    }
    function drawTriad() {
      var ctx = triad.getContext('2d'), c = 45;
      ctx.clearRect(0, 0, 90, 90);
      var m = new THREE.Matrix4().extractRotation(camera.matrixWorldInverse);
      [['x', [1, 0, 0], '#c0392b'], ['y', [0, 1, 0], '#27ae60'], ['z', [0, 0, 1], '#2471a3']].forEach(function (t) {
        var d = new THREE.Vector3().fromArray(t[1]).applyMatrix4(world.matrixWorld.clone().setPosition(0, 0, 0)).applyMatrix4(m);
        ctx.strokeStyle = t[2]; ctx.fillStyle = t[2]; ctx.lineWidth = 2;
        ctx.beginPath(); ctx.moveTo(c, c); ctx.lineTo(c + 30 * d.x, c - 30 * d.y); ctx.stroke();
        ctx.font = 'bold 12px sans-serif'; ctx.fillText(t[0], c + 36 * d.x - 4, c - 36 * d.y + 4);
      });
    }
    function render() {
      if (state.playing) state.phase = 2 * Math.PI * ((performance.now() - state.start) / 1000 / PERIOD_S % 1);
      shapeAt(state.phase); place();
      renderer.render(scene, camera);
      drawTriad();
    }
    // At most FPS frames a second: the view stays light on a machine drawing WebGL in software.
    var FPS = 24, last = 0;
    function frame(now) {
      if (now - last >= 1000 / FPS) { last = now; render(); root.gdFrame = (root.gdFrame || 0) + 1; }
      requestAnimationFrame(frame);
    }

    var ui = window.geardynViewPanel.build(root, side, data, select, selectOds);
    function scaleNote(what) {
      note.textContent = 'motion scaled: ' + what + ' drawn as ' + amp.value + ' % of the train\'s size (' +
                         fmt(1e3 * extent, 3) + ' mm); rotations as displacement at the part\'s radius';
    }
    function select(i) {
      state.mode = i; state.ods = -1; state.shape = data.modes[i];
      var m = data.modes[i];
      titleEl.innerHTML = '';
      el('b', null, titleEl, 'Mode ' + m.mode + ': ' + fmt(m.frequency_hz, 5) + ' Hz');
      el('span', null, titleEl, ' · ' + m.type + ' · ζ = ' + fmt(100 * m.damping_ratio, 3) + ' %' +
         (data.speed_rpm ? ' · at ' + fmt(data.speed_rpm, 5) + ' rpm' : ''));
      titleEl.setAttribute('data-frequency-hz', String(m.frequency_hz));
      ui.highlight(i, -1);
      scaleNote('largest displacement');
    }
    // An operating deflection shape of the forced response (forced_ods.csv): its amplitudes
    // are physical, the largest is named in the title.
    function selectOds(j) {
      var o = data.ods[j];
      state.ods = j; state.shape = o;
      titleEl.innerHTML = '';
      el('b', null, titleEl, 'ODS at ' + fmt(o.speed_rpm, 5) + ' rpm, ' + o.mesh + ' order ' + o.order + ': ' +
         fmt(o.frequency_hz, 5) + ' Hz');
      el('span', null, titleEl, ' · largest amplitude ' + fmt(1e6 * o.largest_m, 3) + ' µm');
      titleEl.setAttribute('data-frequency-hz', String(o.frequency_hz));
      ui.highlight(-1, j);
      scaleNote('largest amplitude (' + fmt(1e6 * o.largest_m, 3) + ' µm)');
    }
    play.onclick = function () {
      state.playing = !state.playing; play.textContent = state.playing ? 'pause' : 'play';
      state.start = performance.now() - state.phase / (2 * Math.PI) * PERIOD_S * 1000;
    };
    amp.oninput = function () { if (state.ods >= 0) selectOds(state.ods); else select(state.mode); };
    ghostBox.onchange = function () { ghostLines.visible = ghostBox.checked; };
    // Hover: the part's name (nearest body) in a tooltip.
    var ray = new THREE.Raycaster(), mouse = new THREE.Vector2();
    renderer.domElement.addEventListener('mousemove', function (ev) {
      var r = renderer.domElement.getBoundingClientRect();
      mouse.set((ev.clientX - r.left) / r.width * 2 - 1, -(ev.clientY - r.top) / r.height * 2 + 1);
      ray.setFromCamera(mouse, camera);
      var hit = ray.intersectObject(world, true)[0];
      var name = null;
      if (hit) for (var o = hit.object; o && !name; o = o.parent) { var i = nodes.indexOf(o); if (i >= 0) name = bodies[i].name; }
      tip.style.display = name ? 'block' : 'none';
      if (name) { tip.textContent = name; tip.style.left = (ev.clientX - r.left + 12) + 'px'; tip.style.top = (ev.clientY - r.top + 8) + 'px'; }
    });
    window.addEventListener('resize', resize);
    resize(); shapeAt(0); place(); times.placed = performance.now() - t0;
    select(0);
    root.gdView = {
      select: select, selectOds: selectOds, modes: data.modes.length,
      setPlaying: function (on) { if (on !== state.playing) play.onclick(); },
      setPhase: function (p) { state.phase = p; render(); }
    };
    render(); times.first = performance.now() - t0;
    root.setAttribute('data-times', JSON.stringify(times));
    root.setAttribute('data-rendered-ms', String(performance.now()));
    root.setAttribute('data-rendered', '1');
    var started = false;
    root.gdStart = function () { if (!started) { started = true; state.start = performance.now(); requestAnimationFrame(frame); } };
    setTimeout(function () { snapshotGhost(); render(); if (!window.geardynView3dWait) root.gdStart(); }, 0);

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

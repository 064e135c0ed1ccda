// geardyn 3-D view, the scene: renderer, lights and camera, the parts (view3d_parts.js) on one
// group per body, the flexible shafts' segments, and how a displacement vector moves them.
// window.geardynScene.create(lib, wrap, data) -> {extent, kinds, place(disp), render(),
// snapshotGhost(), ghost, resize(), drawTriad(canvas), hover(tip)}.
// disp holds per body (x, y, z, θ, θ_y, θ_z) [m, rad]: the body's group is moved and turned by
// them; a flexible shaft bends between its nodes by the beam's cubic (Hermite) shape functions
// (Przemieniecki 1968, eq. 5.104: v = N1 v_a + N2 L θ_z,a + N3 v_b + N4 L θ_z,b, and w with −θ_y,
// the node rotations about y and z being −dw/dx and dv/dx).
window.geardynScene = (function () {
  'use strict';
  var SUB = 4;  // segments a flexible shaft's element is drawn with

  function hermite(a, b, da, db, L, xi) {
    var xi2 = xi * xi, xi3 = xi2 * xi;
    var n1 = 1 - 3 * xi2 + 2 * xi3, n2 = L * (xi - 2 * xi2 + xi3), n3 = 3 * xi2 - 2 * xi3, n4 = L * (xi3 - xi2);
    return [a[0] + xi * L + (1 - xi) * da[0] + xi * db[0],
            a[1] + xi * (b[1] - a[1]) + n1 * da[1] + n2 * da[5] + n3 * db[1] + n4 * db[5],
            a[2] + xi * (b[2] - a[2]) + n1 * da[2] - n2 * da[4] + n3 * db[2] - n4 * db[4]];
  }

  function create(lib, wrap, data) {
    var THREE = lib.THREE, Parts = window.geardynParts, bodies = data.bodies;
    var renderer = new THREE.WebGLRenderer({antialias: true});
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    wrap.insertBefore(renderer.domElement, wrap.firstChild);
    var scene = new THREE.Scene();
    scene.background = new THREE.Color(0xf3f5f7);
    scene.add(new THREE.HemisphereLight(0xffffff, 0x7d8894, 1.6));
    var key = new THREE.DirectionalLight(0xffffff, 2.2), fill = new THREE.DirectionalLight(0xffffff, 0.8);
    scene.add(key); scene.add(fill);
    var world = new THREE.Group(), ghost = new THREE.Group();
    world.rotation.x = -Math.PI / 2;  // the train's z up
    scene.add(world); scene.add(ghost);

    var built = Parts.build(THREE, data), nodes = [], segments = [];
    bodies.forEach(function (b) {
      var n = new THREE.Group();
      n.position.set(b.c[0], b.c[1], b.c[2]);
      world.add(n); nodes.push(n);
    });
    built.parts.forEach(function (p) { nodes[p.body].add(p.object); });
    var unit = new THREE.CylinderGeometry(1, 1, 1, 40, 1, false);
    var shaftMaterial = Parts.material(THREE, Parts.COLOURS.shaft);
    built.elements.forEach(function (e) {
      for (var k = 0; k < SUB; ++k) {
        var m = new THREE.Mesh(unit, shaftMaterial);
        m.userData.shaft = e.shaft;
        world.add(m); segments.push({mesh: m, e: e, k: k});
      }
    });

    var v = new THREE.Vector3(), axis = new THREE.Vector3(), up = new THREE.Vector3(0, 1, 0);
    function place(disp) {
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
        s.mesh.quaternion.setFromUnitVectors(up, v.divideScalar(len || 1));
        s.mesh.scale.set(s.e.radius, len, s.e.radius);
      });
    }
    // A flexible housing's outer surface (view3d.py, _housing_surface.py), semi-transparent and
    // at rest; not picked by the hover (the parts inside it are).
    if (data.housing_surface) {
      var hs = data.housing_surface, skin = new THREE.BufferGeometry();
      skin.setAttribute('position', new THREE.Float32BufferAttribute(hs.positions, 3));
      skin.setIndex(hs.triangles);
      skin.computeVertexNormals();
      var housing = new THREE.Mesh(skin, new THREE.MeshStandardMaterial({
        color: 0x8fa3b8, transparent: true, opacity: 0.15, side: THREE.DoubleSide,
        depthWrite: false, roughness: 0.8, flatShading: true}));
      housing.userData.housing = true;
      housing.renderOrder = 1;
      world.add(housing);
    }
    var rest = new Float64Array(6 * bodies.length);
    place(rest);
    // The train's size from its parts at rest; a train long along its shafts is seen from the
    // side and above, a flat one (a planetary stage) obliquely from its axis.
    var box = new THREE.Box3().setFromObject(world), size = box.getSize(new THREE.Vector3());
    var extent = Math.max(size.x, size.y, size.z, 1e-3), centre = box.getCenter(new THREE.Vector3());
    var camera = new THREE.PerspectiveCamera(35, 1, extent / 100, extent * 100);
    var view = size.x > 0.6 * Math.max(size.y, size.z) ? [0.4, 0.85, 1.55] : [1.25, 0.8, 1.5];
    camera.position.set(centre.x + view[0] * extent, centre.y + view[1] * extent, centre.z + view[2] * extent);
    key.position.set(1.5 * extent, 3 * extent, 2 * extent);
    fill.position.set(-2 * extent, 0.5 * extent, -1.5 * extent);
    var orbit = new lib.OrbitControls(camera, renderer.domElement);
    orbit.target.copy(centre); orbit.enableDamping = false; orbit.update();

    // The undeformed train in grey: the pitch circles and the shafts' axes at rest.
    function snapshotGhost() {
      place(rest);
      world.updateMatrixWorld(true);
      var mat = new THREE.LineBasicMaterial({color: 0x9aa3ad});
      world.traverse(function (o) {
        if (o.type !== 'Line') return;
        var line = new THREE.Line(o.geometry, mat);
        line.applyMatrix4(o.matrixWorld);
        ghost.add(line);
      });
      data.geometry.shafts.forEach(function (s) {
        var pts = s.bodies.map(function (n) {
          var c = bodies[built.index[n]].c;
          return new THREE.Vector3(c[0], c[1], c[2]).applyMatrix4(world.matrixWorld);
        });
        if (pts.length > 1) ghost.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(pts), mat));
      });
    }
    function resize() {
      var w = wrap.clientWidth || 800, h = wrap.clientHeight || 520;
      renderer.setSize(w, h, true);
      camera.aspect = w / h; camera.updateProjectionMatrix();
    }
    // The train's axes as the camera sees them, in a small 2-D canvas.
    function drawTriad(canvas) {
      var ctx = canvas.getContext('2d'), c = 45;
      ctx.clearRect(0, 0, 90, 90);
      var m = new THREE.Matrix4().extractRotation(camera.matrixWorldInverse);
      var frame = world.matrixWorld.clone().setPosition(0, 0, 0);
      [['x', [1, 0, 0], '#c0392b'], ['y', [0, 1, 0], '#27ae60'], ['z', [0, 0, 1], '#2471a3']].forEach(function (t) {
        var d = new THREE.Vector3().fromArray(t[1]).applyMatrix4(frame).applyMatrix4(m);
        ctx.strokeStyle = t[2]; ctx.fillStyle = t[2]; ctx.lineWidth = 2;
        ctx.beginPath(); ctx.moveTo(c, c); ctx.lineTo(c + 30 * d.x, c - 30 * d.y); ctx.stroke();
        ctx.font = 'bold 12px sans-serif'; ctx.fillText(t[0], c + 36 * d.x - 4, c - 36 * d.y + 4);
      });
    }
    // Hovering a part names it (with its size) in `tip`.
    function hover(tip) {
      var ray = new THREE.Raycaster(), mouse = new THREE.Vector2();
      ray.params.Line.threshold = 0;  // the solids name the parts, not the circles on them
      renderer.domElement.addEventListener('mousemove', function (ev) {
        var r = renderer.domElement.getBoundingClientRect(), name = null;
        mouse.set((ev.clientX - r.left) / r.width * 2 - 1, -(ev.clientY - r.top) / r.height * 2 + 1);
        ray.setFromCamera(mouse, camera);
        var hit = ray.intersectObject(world, true).filter(function (h) {
          return h.object.isMesh && !h.object.userData.housing;
        })[0];
        for (var o = hit && hit.object; o && !name; o = o.parent) {
          var i = nodes.indexOf(o);
          if (o.userData.label) name = o.userData.label;
          else if (i >= 0) name = bodies[i].name;
          else if (o.userData.shaft) name = 'shaft ' + o.userData.shaft;
        }
        tip.style.display = name ? 'block' : 'none';
        if (name) {
          tip.textContent = name;
          tip.style.left = (ev.clientX - r.left + 12) + 'px'; tip.style.top = (ev.clientY - r.top + 8) + 'px';
        }
      });
    }
    // fn() whenever the camera moves (a paused view draws only then and on other changes).
    function onCameraChange(fn) { orbit.addEventListener('change', fn); }
    return {extent: extent, kinds: built.kinds, ghost: ghost, place: place, resize: resize,
            snapshotGhost: snapshotGhost, drawTriad: drawTriad, hover: hover,
            onCameraChange: onCameraChange,
            render: function () { renderer.render(scene, camera); }};
  }
  return {create: create};
})();

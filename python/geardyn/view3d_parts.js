// geardyn 3-D view, the parts: shafts, gears (teeth, pitch and tip circles, helix lines),
// planets, carriers, bearings, couplings and disks as three.js solids, built in the train's frame
// (x along the shafts, (y, z) across, z up) from summary.json results.geometry
// (src/analysis/train_geometry.cpp). Used by view3d.js; window.geardynParts.build(THREE, data).
window.geardynParts = (function () {
  'use strict';
  var COLOURS = {
    shaft: 0x9aa4ae, gear: [0xd4a93c, 0x4f81bd, 0x6aa84f, 0xc0504d, 0x8e7cc3, 0x46bdc6],
    planet: 0x8e7cc3, ring: 0x7f8c8d, carrier: 0x3d7a66, bearing: 0x2f5597, coupling: 0xe07b39,
    disk: 0x5d6166, marker: 0xd62728, line: 0x222222, pitch: 0x111111
  };
  // [kind, label, colour]: the legend shows the kinds the train has.
  var LEGEND = [['shaft', 'shaft', COLOURS.shaft], ['gear', 'gear (black: pitch circle)', COLOURS.gear[0]],
                ['ring', 'ring gear', COLOURS.ring], ['planet', 'planet', COLOURS.planet],
                ['carrier', 'carrier and pins', COLOURS.carrier], ['bearing', 'bearing', COLOURS.bearing],
                ['coupling', 'coupling', COLOURS.coupling], ['disk', 'disk, lumped rotor', COLOURS.disk],
                ['marker', 'torsion marker (red)', COLOURS.marker]];
  var DENSITY = 7850;  // [kg/m³] steel: the size of a lumped rotor drawn as a solid cylinder

  function material(THREE, colour, extra) {
    var m = new THREE.MeshPhongMaterial({color: colour, shininess: 45, specular: 0x333333});
    if (extra) Object.assign(m, extra);
    return m;
  }

  // A solid of revolution about x from x0 to x1 between radii rin (0: solid) and rout, with an
  // outline `outer` (a THREE.Shape in the (y, z) plane) when given.
  function extrudeX(THREE, shape, x0, x1, segments) {
    var g = new THREE.ExtrudeGeometry(shape, {depth: x1 - x0, bevelEnabled: false,
                                              curveSegments: segments || 64});
    g.rotateY(Math.PI / 2);  // extrusion along z -> along x
    g.translate(x0, 0, 0);
    return g;
  }
  function circlePath(THREE, r, hole) {
    var p = hole ? new THREE.Path() : new THREE.Shape();
    p.absarc(0, 0, r, 0, 2 * Math.PI, !!hole);
    return p;
  }
  function annulus(THREE, rin, rout, x0, x1, colour) {
    var s = circlePath(THREE, rout, false);
    if (rin > 0) s.holes.push(circlePath(THREE, rin, true));
    return new THREE.Mesh(extrudeX(THREE, s, x0, x1), material(THREE, colour));
  }
  // Teeth outline: trapezoids between the root and tip radii (z teeth), outward or, for an
  // internal gear (tip < root), inward. The ExtrudeGeometry shape is in (u, v) = (z', y')
  // after rotateY; the outline is symmetric, so orientation does not matter.
  function toothOutline(THREE, teeth, root, tip, hole) {
    var p = hole ? new THREE.Path() : new THREE.Shape(), pitch = 2 * Math.PI / teeth;
    var halfRoot = 0.30 * pitch, halfTip = 0.16 * pitch;
    for (var k = 0; k < teeth; ++k) {
      var a = k * pitch, pts = [[root, a - 0.5 * pitch], [root, a - halfRoot], [tip, a - halfTip],
                                [tip, a + halfTip], [root, a + halfRoot]];
      if (hole) pts.reverse();
      pts.forEach(function (q, i) {
        var x = q[0] * Math.cos(q[1]), y = q[0] * Math.sin(q[1]);
        if (k === 0 && i === 0) p.moveTo(x, y); else p.lineTo(x, y);
      });
    }
    p.closePath();
    return p;
  }
  function circleLine(THREE, r, x, colour, dashed) {
    var pts = [];
    for (var i = 0; i <= 128; ++i) {
      var a = 2 * Math.PI * i / 128;
      pts.push(new THREE.Vector3(x, r * Math.cos(a), r * Math.sin(a)));
    }
    var g = new THREE.BufferGeometry().setFromPoints(pts);
    var m = dashed ? new THREE.LineDashedMaterial({color: colour, dashSize: r * 0.06, gapSize: r * 0.04})
                   : new THREE.LineBasicMaterial({color: colour});
    var line = new THREE.Line(g, m);
    if (dashed) line.computeLineDistances();
    return line;
  }
  // Lines along the tooth tips across the face, twisted by the helix: Δφ = b tan β / r.
  function helixLines(THREE, teeth, r, b, beta, colour) {
    var pts = [], twist = b * Math.tan(beta) / r, pitch = 2 * Math.PI / teeth;
    for (var k = 0; k < teeth; ++k) {
      var a = k * pitch;
      pts.push(new THREE.Vector3(-b / 2, r * Math.cos(a - twist / 2), r * Math.sin(a - twist / 2)));
      pts.push(new THREE.Vector3(b / 2, r * Math.cos(a + twist / 2), r * Math.sin(a + twist / 2)));
    }
    return new THREE.LineSegments(new THREE.BufferGeometry().setFromPoints(pts),
                                  new THREE.LineBasicMaterial({color: colour}));
  }
  // A red bar on both faces from the bore to the tip, pointing up (+z) at rest: the rotation
  // of a marked part is the torsion of the mode.
  function marker(THREE, rin, rout, x0, x1) {
    var group = new THREE.Group(), len = rout - rin, width = Math.max(0.05 * rout, 0.002);
    [x0, x1].forEach(function (x, i) {
      var bar = new THREE.Mesh(new THREE.BoxGeometry(0.002 + 0.01 * len, len, width),
                               material(THREE, COLOURS.marker, {shininess: 10}));
      bar.position.set(x + (i ? 1 : -1) * (0.001 + 0.005 * len), 0, rin + len / 2);
      bar.rotation.x = Math.PI / 2;
      group.add(bar);
    });
    return group;
  }

  function mm(v) {  // a length [m] in mm, three significant digits
    var s = (1e3 * v).toPrecision(3);
    return (s.indexOf('.') >= 0 && s.indexOf('e') < 0 ? s.replace(/\.?0+$/, '') : String(Number(s))) + ' mm';
  }
  // What hovering a gear says: name, teeth, module, helix and face width, in units.
  function gearLabel(name, g) {
    var m = 2 * g.pitch_radius_m * Math.cos(g.helix_angle_deg * Math.PI / 180) / g.teeth;
    return name + ': ' + (g.internal ? 'ring gear, ' : '') + g.teeth + ' teeth, m_n ' + mm(m) + ', ' +
           (g.hand === 'spur' ? 'spur' : 'helical ' + Math.abs(g.helix_angle_deg).toPrecision(3) + '°, ' + g.hand + ' hand') +
           ', b ' + mm(g.face_width_m) + ', d ' + mm(2 * g.pitch_radius_m);
  }

  function gear(THREE, g, colour) {
    var group = new THREE.Group(), b = g.face_width_m, x0 = -b / 2, x1 = b / 2;
    var teeth = Math.min(g.teeth, 240);
    if (g.internal) {
      var rim = g.root_radius_m + Math.max(0.25 * (g.root_radius_m - g.tip_radius_m) * 4, 0.01 * g.pitch_radius_m);
      var s = circlePath(THREE, rim, false);
      s.holes.push(toothOutline(THREE, teeth, g.root_radius_m, g.tip_radius_m, true));
      group.add(new THREE.Mesh(extrudeX(THREE, s, x0, x1, 96), material(THREE, COLOURS.ring)));
      group.add(marker(THREE, g.root_radius_m, rim, x0, x1));
    } else {
      var outline = toothOutline(THREE, teeth, g.root_radius_m, g.tip_radius_m, false);
      if (g.bore_radius_m > 0) outline.holes.push(circlePath(THREE, g.bore_radius_m, true));
      group.add(new THREE.Mesh(extrudeX(THREE, outline, x0, x1, 96), material(THREE, colour)));
      group.add(marker(THREE, Math.max(g.bore_radius_m, 0.2 * g.root_radius_m), g.root_radius_m, x0, x1));
      group.add(helixLines(THREE, teeth, g.tip_radius_m * 1.001, b, g.helix_angle_deg * Math.PI / 180, COLOURS.line));
    }
    [x0 - 1e-4, x1 + 1e-4].forEach(function (x) {
      group.add(circleLine(THREE, g.pitch_radius_m, x, COLOURS.pitch, false));
    });
    return group;
  }

  // The radius of shaft `s` at global x [m]: its section there, else a stub's.
  function shaftRadiusAt(shaft, x) {
    var r = 0;
    shaft.sections.forEach(function (c) {
      if (x >= c.start_x_m - 1e-9 && x <= c.start_x_m + c.length_m + 1e-9) r = Math.max(r, c.outer_radius_m);
    });
    return r || shaft.stub_radius;
  }

  // Every part as {body: index, object (in the body's frame, origin at the body's rest centre)}
  // and the flexible shafts' elements {a, b, radius} (drawn by view3d.js between moving nodes).
  function build(THREE, data) {
    var geo = data.geometry, bodies = data.bodies, index = {}, parts = [], elements = [];
    var kinds = {marker: true};
    bodies.forEach(function (b, i) { index[b.name] = i; });
    var span = 0;
    bodies.forEach(function (b) { span = Math.max(span, Math.abs(b.c[0]), Math.abs(b.c[1]), Math.abs(b.c[2])); });
    var gearsOn = {};
    geo.gears.concat(geo.planets).forEach(function (g) {
      (gearsOn[g.body] = gearsOn[g.body] || []).push(g);
    });
    function at(body, object, x, kind, label) {  // object centred at global x on body
      kinds[kind] = true;
      object.userData.label = label || body;
      object.position.x += x - bodies[index[body]].c[0];
      parts.push({body: index[body], object: object});
      return object;
    }
    var shaftsByName = {};
    geo.shafts.forEach(function (s) {
      shaftsByName[s.shaft] = s;
      var gears = [];
      s.bodies.forEach(function (n) { gears = gears.concat(gearsOn[n] || []); });
      var bore = Math.max.apply(null, gears.map(function (g) { return g.bore_radius_m; }).concat([0]));
      var pitch = Math.max.apply(null, gears.map(function (g) { return g.internal ? 0 : g.pitch_radius_m; }).concat([0]));
      s.stub_radius = bore || 0.25 * pitch || 0.01;
    });
    geo.shafts.forEach(function (s) {
      if (s.flexible && s.bodies.length > 1) {
        for (var k = 0; k + 1 < s.bodies.length; ++k) {
          var a = index[s.bodies[k]], b = index[s.bodies[k + 1]];
          kinds.shaft = true;
          var radius = shaftRadiusAt(s, 0.5 * (bodies[a].c[0] + bodies[b].c[0]));
          elements.push({a: a, b: b, radius: radius, shaft: s.shaft + ': d ' + mm(2 * radius)});
        }
        return;
      }
      var body = s.bodies[0], x = bodies[index[body]].c[0];
      if (s.sections.length) {
        s.sections.forEach(function (c) {
          at(body, annulus(THREE, c.inner_radius_m, c.outer_radius_m, c.start_x_m - x, c.start_x_m + c.length_m - x, COLOURS.shaft), x, 'shaft',
             'shaft ' + s.shaft + ': d ' + mm(2 * c.outer_radius_m));
        });
        return;
      }
      var gears = gearsOn[body] || [];
      if (gears.length) {  // a lumped member carrying gears: a stub behind them
        var internal = gears.some(function (g) { return g.internal; });
        if (internal) return;  // a ring: its rim is drawn with the gear
        var w = gears[0].face_width_m;
        at(body, annulus(THREE, 0, s.stub_radius, -2.5 * w, -0.5 * w, COLOURS.shaft), x, 'shaft');
        return;
      }
      if (geo.carriers.some(function (c) { return c.body === body; })) return;
      // A lumped rotor (a motor): a steel cylinder of its mass and polar inertia,
      // r = sqrt(2 J / m), length m / (ρ π r²), beside what it is coupled to.
      var r = s.mass_kg > 0 ? Math.sqrt(2 * s.polar_inertia_kg_m2 / s.mass_kg) : 0.05;
      var len = Math.min(Math.max(s.mass_kg / (DENSITY * Math.PI * r * r), 0.2 * r), 4 * r);
      var side = -1, gap = 0.06 * Math.max(span, 0.1);
      geo.couplings.forEach(function (c) { if (c.body_b === body) side = 1; });
      var from = side < 0 ? -gap - len : gap, to = side < 0 ? -gap : gap + len;
      var drum = annulus(THREE, 0, r, from, to, COLOURS.disk);
      drum.add(marker(THREE, 0.3 * r, r, from, to));
      at(body, drum, x, 'disk', 'rotor ' + s.shaft + ': ' + s.mass_kg.toPrecision(3) + ' kg, ' +
         s.polar_inertia_kg_m2.toPrecision(3) + ' kg m²');
      s.drum = {from: from, to: to, radius: r};
    });
    var colourOf = {};
    geo.gears.forEach(function (g, i) {
      var c = colourOf[g.teeth + ':' + g.face_width_m] = COLOURS.gear[Object.keys(colourOf).length % COLOURS.gear.length];
      at(g.body, gear(THREE, g, c), g.axial_x_m, g.internal ? 'ring' : 'gear', gearLabel(g.gear, g));
    });
    geo.planets.forEach(function (g) { at(g.body, gear(THREE, g, COLOURS.planet), g.axial_x_m, 'planet', gearLabel(g.planet, g)); });
    geo.carriers.forEach(function (c) {
      var planets = geo.planets.filter(function (p) { return p.carrier_body === c.body; });
      if (!planets.length) return;
      var p = planets[0], w = p.face_width_m, x = p.axial_x_m, xc = bodies[index[c.body]].c;
      var plate = annulus(THREE, 0.3 * c.orbit_radius_m, c.orbit_radius_m + 0.5 * p.root_radius_m,
                          -1.3 * w, -0.9 * w, COLOURS.carrier);
      planets.forEach(function (q) {
        var pc = bodies[index[q.body]].c, pin = new THREE.Mesh(
          new THREE.CylinderGeometry(0.3 * p.root_radius_m, 0.3 * p.root_radius_m, 0.9 * w, 32),
          material(THREE, COLOURS.carrier));
        pin.rotation.z = Math.PI / 2;
        pin.position.set(-0.45 * w, pc[1] - xc[1], pc[2] - xc[2]);
        plate.add(pin);
      });
      plate.add(marker(THREE, 0.3 * c.orbit_radius_m, c.orbit_radius_m, -1.3 * w, -0.9 * w));
      at(c.body, plate, x, 'carrier', 'carrier ' + c.shaft + ': planet orbit r ' + mm(c.orbit_radius_m));
    });
    geo.bearings.forEach(function (b) {
      var shaft = shaftsByName[bodyShaft(geo, b.body)] || {sections: [], stub_radius: 0.01};
      var r = shaftRadiusAt(shaft, b.axial_x_m), w = Math.max(0.9 * r, 0.008);
      var ring = annulus(THREE, 1.02 * r, 1.02 * r + Math.max(0.6 * r, 0.006), -w / 2, w / 2, COLOURS.bearing);
      ring.add(annulus(THREE, 1.02 * r + Math.max(0.6 * r, 0.006), 1.02 * r + Math.max(0.9 * r, 0.009),
                       -0.35 * w, 0.35 * w, 0x1d3766));
      at(b.body, ring, b.axial_x_m, 'bearing', 'bearing ' + b.bearing + ' (' + b.type + ')');
    });
    geo.disks.forEach(function (d) {
      var r = d.mass_kg > 0 ? Math.sqrt(2 * d.polar_inertia_kg_m2 / d.mass_kg) : 0.05;
      var w = Math.max(d.mass_kg / (DENSITY * Math.PI * r * r), 0.04 * r);
      var disk = annulus(THREE, 0, r, -w / 2, w / 2, COLOURS.disk);
      disk.add(marker(THREE, 0.15 * r, r, -w / 2, w / 2));
      at(d.body, disk, d.axial_x_m, 'disk', 'disk ' + d.disk + ': ' + d.mass_kg.toPrecision(3) + ' kg, ' +
         d.polar_inertia_kg_m2.toPrecision(3) + ' kg m²');
    });
    geo.couplings.forEach(function (c) {
      var a = bodies[index[c.body_a]], b = bodies[index[c.body_b]];
      var sa = shaftsByName[bodyShaft(geo, c.body_a)], sb = shaftsByName[bodyShaft(geo, c.body_b)];
      // From the end of shaft a (its last section, its rotor drum, or its node) to the start
      // of shaft b: a rigid shaft's body sits at its mass centre, not at its ends.
      var from = a.c[0], to = b.c[0];
      if (sa && sa.drum) from = a.c[0] + sa.drum.to;
      else if (sa && sa.sections.length) from = sectionEnd(sa);
      if (sb && sb.drum) to = b.c[0] + sb.drum.from;
      else if (sb && sb.sections.length) to = sb.sections[0].start_x_m;
      if (to - from < 1e-4) { var mid = 0.5 * (from + to); from = mid - 0.01; to = mid + 0.01; }
      var r = 1.8 * Math.max(sb ? shaftRadiusAt(sb, to) : shaftRadiusAt(sa, from), 0.004);
      var hub = annulus(THREE, 0, r, from - a.c[0], to - a.c[0], COLOURS.coupling);
      hub.userData.label = 'coupling ' + c.coupling;
      parts.push({body: index[c.body_a], object: hub});
      kinds.coupling = true;
    });
    return {parts: parts, elements: elements, span: span, kinds: kinds, index: index};
  }

  function sectionEnd(shaft) {
    var last = shaft.sections[shaft.sections.length - 1];
    return last.start_x_m + last.length_m;
  }

  function bodyShaft(geo, body) {
    var found = null;
    geo.shafts.forEach(function (s) { if (s.bodies.indexOf(body) >= 0) found = s.shaft; });
    return found;
  }

  return {build: build, material: material, COLOURS: COLOURS, LEGEND: LEGEND};
})();

// The viewer of an `implicitfit view` page (docs/view.md): reads the page's data (layers of
// points and triangle meshes, typed arrays in base64; view/page_data.h), draws them with three.js,
// and builds the panel (layers, colour modes, clipping plane, legends). Options come from the
// page's defaults (data.options, set by the command) overridden by the URL fragment,
//   #clip=z,0.5&az=-60&el=25&zoom=1&color=residual&hide=0,2&ui=0&size=2
// so that a test (or a link in a report) can fix the picture: see docs/view.md for every key.
(function () {
  'use strict';
  var data = JSON.parse(document.getElementById('implicitfit-view-data').textContent);

  // ---- options: defaults < data.options < URL fragment
  function parseFragment(hash) {
    var out = {};
    hash.replace(/^#/, '').split('&').forEach(function (kv) {
      if (!kv) return;
      var i = kv.indexOf('=');
      var k = decodeURIComponent(i < 0 ? kv : kv.slice(0, i));
      out[k] = i < 0 ? '1' : decodeURIComponent(kv.slice(i + 1));
    });
    return out;
  }
  var opts = Object.assign({ ui: '1', az: '-60', el: '25', zoom: '1', fov: '30', color: 'auto',
                             bg: '#ffffff', unassigned: '1', up: 'z', params: '0' },
                           data.options || {}, parseFragment(location.hash));
  function numbers(text) { return String(text).split(',').map(Number); }

  // ---- base64 typed arrays
  function decode(b64, Type) {
    var bin = atob(b64), n = bin.length, bytes = new Uint8Array(n);
    for (var i = 0; i < n; ++i) bytes[i] = bin.charCodeAt(i);
    return new Type(bytes.buffer);
  }

  // ---- colours
  // Primitive k: Trubetskoy's list of 20 distinct colours less its grey (the lightest last: the
  // largest primitives come first), then hues by the golden angle. Grey is kept for unassigned
  // points, red for the inside (back faces) of surfaces.
  var PALETTE = ['#4363d8', '#f58231', '#3cb44b', '#911eb4', '#42d4f4', '#f032e6', '#9a6324',
                 '#808000', '#000075', '#e6194b', '#469990', '#bfef45', '#800000', '#ffe119',
                 '#000000', '#fabed4', '#dcbeff', '#aaffc3', '#ffd8b1'];
  var UNASSIGNED = '#a3a3a3', INSIDE = '#d03a2f';
  var PLAIN = ['#4a6fa5', '#d08c2e', '#4f9a58', '#8e5ea2'];
  var MESH = ['#9dbbd9', '#c9b48f', '#a9cfa0', '#c7a9d6'];
  function primitiveColour(k) {
    if (k < PALETTE.length) return new THREE.Color(PALETTE[k]);
    var c = new THREE.Color();
    c.setHSL(((k - PALETTE.length) * 0.618034) % 1, 0.65, 0.38 + 0.2 * ((k >> 1) % 2));
    return c;
  }
  // Signed residuals: blue (inside, f < 0) - grey (on the surface) - red (outside), clamped at
  // +-scale.
  var RESIDUAL_STOPS = [new THREE.Color('#3b4cc0'), new THREE.Color('#b4b4b4'),
                        new THREE.Color('#b40426')];
  function residualColour(r, scale, out) {
    var t = Math.max(-1, Math.min(1, scale > 0 ? r / scale : 0));
    out.copy(RESIDUAL_STOPS[1]).lerp(RESIDUAL_STOPS[t < 0 ? 0 : 2], Math.abs(t));
    return out;
  }

  // ---- scene
  var container = document.getElementById('canvas');
  var renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setSize(window.innerWidth, window.innerHeight);
  container.appendChild(renderer.domElement);
  var scene = new THREE.Scene();
  scene.background = new THREE.Color(opts.bg);
  var camera = new THREE.PerspectiveCamera(Number(opts.fov), window.innerWidth / window.innerHeight,
                                           1e-3, 1e3);
  // The up axis (z for scans and CAD parts; up=y for models made y-up).
  var UP = { x: [1, 0, 0], y: [0, 1, 0], z: [0, 0, 1] }[opts.up] || [0, 0, 1];
  camera.up.fromArray(UP);
  scene.add(camera);
  scene.add(new THREE.AmbientLight(0xffffff, 0.45));
  var headlight = new THREE.DirectionalLight(0xffffff, 0.6);
  headlight.position.set(0.3, 0.5, 1);
  camera.add(headlight);

  var centre = new THREE.Vector3().fromArray(data.centre || [0, 0, 0]);
  var boxMin = new THREE.Vector3().fromArray(data.box_min || [-1, -1, -1]).sub(centre);
  var boxMax = new THREE.Vector3().fromArray(data.box_max || [1, 1, 1]).sub(centre);
  var radius = Math.max(0.5 * boxMin.distanceTo(boxMax), 1e-9);
  camera.near = radius * 1e-3;
  camera.far = radius * 1e3;

  var hidden = {};
  if (opts.hide === 'all') data.layers.forEach(function (_, i) { hidden[i] = true; });
  else if (opts.hide) numbers(opts.hide).forEach(function (i) { hidden[i] = true; });

  var defaultSize = Number(opts.size || 0);
  var meshes = 0, clouds = 0;
  var layers = data.layers.map(function (L, index) {
    var entry = { data: L, index: index, object: null, mode: null, modes: [],
                  ordinal: L.type === 'points' ? clouds++ : meshes++ };
    if (L.type === 'points') buildPoints(entry); else buildMesh(entry);
    entry.object.visible = !hidden[index];
    scene.add(entry.object);
    return entry;
  });

  function buildPoints(entry) {
    var L = entry.data, n = L.count;
    var q = decode(L.positions, Uint16Array);
    var geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(q, 3, true));
    entry.colours = new Uint8Array(3 * n);
    geometry.setAttribute('color', new THREE.BufferAttribute(entry.colours, 3, true));
    if (L.labels) entry.labels = decode(L.labels.data, L.labels.type === 'int32' ? Int32Array
                                                                                 : Int16Array);
    if (L.residuals) entry.residuals = decode(L.residuals, Float32Array);
    if (entry.labels) entry.modes.push('primitive');
    if (entry.residuals) entry.modes.push('residual');
    entry.modes.push('plain');
    entry.mode = opts.color !== 'auto' && entry.modes.indexOf(opts.color) >= 0 ? opts.color
                 : (L.colour && entry.modes.indexOf(L.colour) >= 0 ? L.colour : entry.modes[0]);
    entry.scale = Number(opts.scale || L.residual_scale || 0);
    var size = defaultSize || (n <= 20000 ? 3 : n <= 200000 ? 2 : 1);
    var material = new THREE.PointsMaterial({ size: size, sizeAttenuation: false,
                                              vertexColors: THREE.VertexColors });
    var points = new THREE.Points(geometry, material);
    // Quantised positions in [0, 1]^3 (normalized uint16) mapped onto the layer's box.
    var origin = new THREE.Vector3().fromArray(L.origin).sub(centre);
    points.position.copy(origin);
    points.scale.fromArray(L.extent.map(function (e) { return e > 0 ? e : 1e-12; }));
    points.frustumCulled = false;
    entry.object = points;
    colourPoints(entry);
  }

  function colourPoints(entry) {
    var n = entry.data.count, c = new THREE.Color(), out = entry.colours;
    var plain = new THREE.Color(PLAIN[entry.ordinal % PLAIN.length]);
    var grey = new THREE.Color(UNASSIGNED), palette = [];
    var showUnassigned = opts.unassigned !== '0';
    var drawn = 0;
    var idx = [];
    for (var i = 0; i < n; ++i) {
      var col = plain, keep = true;
      if (entry.mode === 'primitive') {
        var k = entry.labels[i];
        if (k < 0) { col = grey; keep = showUnassigned; }
        else col = palette[k] || (palette[k] = primitiveColour(k));
      } else if (entry.mode === 'residual') {
        col = residualColour(entry.residuals[i], entry.scale, c);
      }
      out[3 * i] = Math.round(col.r * 255);
      out[3 * i + 1] = Math.round(col.g * 255);
      out[3 * i + 2] = Math.round(col.b * 255);
      if (keep) idx.push(i);
    }
    var geometry = entry.object.geometry;
    geometry.attributes.color.needsUpdate = true;
    // Hidden unassigned points: an index list of the others.
    if (idx.length < n) geometry.setIndex(new THREE.BufferAttribute(new Uint32Array(idx), 1));
    else geometry.setIndex(null);
  }

  function buildMesh(entry) {
    var L = entry.data;
    var geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(decode(L.vertices, Float32Array), 3));
    geometry.setIndex(new THREE.BufferAttribute(decode(L.triangles, Uint32Array), 1));
    if (L.normals) geometry.setAttribute('normal',
                                         new THREE.BufferAttribute(decode(L.normals, Int8Array), 3, true));
    else geometry.computeVertexNormals();
    var colour = L.colour || MESH[entry.ordinal % MESH.length];
    // Front faces lit in the layer's colour; back faces (the inside of a solid, seen through the
    // clipping plane or an open boundary) flat red. Both pushed back a little so that points
    // lying on the surface stay visible, the back faces further: near a silhouette, where front
    // and back faces meet edge-on, the back faces must stay behind.
    var front = new THREE.MeshLambertMaterial({ color: colour, side: THREE.FrontSide,
                                                polygonOffset: true, polygonOffsetFactor: 1,
                                                polygonOffsetUnits: 1 });
    var back = new THREE.MeshBasicMaterial({ color: INSIDE, side: THREE.BackSide,
                                             polygonOffset: true, polygonOffsetFactor: 4,
                                             polygonOffsetUnits: 4 });
    var group = new THREE.Group();
    group.add(new THREE.Mesh(geometry, front));
    group.add(new THREE.Mesh(geometry, back));
    group.position.fromArray(L.origin).sub(centre);
    entry.colour = colour;
    entry.object = group;
  }

  // ---- camera: orbit around the box centre, from azimuth/elevation (z up) or an explicit
  // camera=x,y,z&target=x,y,z (the files' coordinates).
  var controls = new THREE.OrbitControls(camera, renderer.domElement);
  // With the panel shown, the picture is centred in the free area right of it (a view offset of
  // half the panel's width); framing then fits the box's bounding sphere in that area.
  var panelWidth = 0;
  function setProjection() {
    var W = window.innerWidth, H = window.innerHeight, pw = Math.min(panelWidth, 0.6 * W);
    camera.aspect = (W + pw) / H;
    if (pw > 0) camera.setViewOffset(W + pw, H, 0, 0, W, H); else camera.clearViewOffset();
    camera.updateProjectionMatrix();
    return (W - pw) / H;
  }
  function placeCamera() {
    var aspect = setProjection();
    var target = new THREE.Vector3().addVectors(boxMin, boxMax).multiplyScalar(0.5);
    if (opts.target) target.fromArray(numbers(opts.target)).sub(centre);
    var fov = camera.fov * Math.PI / 180;
    var half = Math.min(fov / 2, Math.atan(Math.tan(fov / 2) * aspect));
    var distance = radius / Math.sin(half) / Number(opts.zoom);
    var position;
    if (opts.camera) {
      position = new THREE.Vector3().fromArray(numbers(opts.camera)).sub(centre);
    } else {
      // Azimuth around the up axis, elevation above the plane across it.
      var az = Number(opts.az) * Math.PI / 180, el = Number(opts.el) * Math.PI / 180;
      var d = [Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el)];
      var k = UP.indexOf(1);  // the up axis takes the elevation component
      var v = [0, 0, 0];
      v[k] = d[2];
      v[(k + 1) % 3] = d[0];
      v[(k + 2) % 3] = d[1];
      position = new THREE.Vector3().fromArray(v).multiplyScalar(distance).add(target);
    }
    camera.position.copy(position);
    controls.target.copy(target);
    camera.lookAt(target);
    controls.update();
  }

  // ---- clipping plane: clip=AXIS,T keeps the part of the scene on the lower side of the plane
  // across AXIS (x, y, z, -x, -y, -z) at the fraction T of the box (0: its low face, 1: its
  // high face), so that a camera on the cut side looks inside.
  var clip = { on: false, axis: 'z', t: 0.5 };
  if (opts.clip && opts.clip !== 'off') {
    var parts = String(opts.clip).split(',');
    clip.on = true;
    clip.axis = parts[0] || 'z';
    clip.t = parts.length > 1 ? Number(parts[1]) : 0.5;
  }
  var plane = new THREE.Plane(new THREE.Vector3(0, 0, -1), 0);
  function applyClip() {
    var negative = clip.axis.charAt(0) === '-', a = clip.axis.replace('-', '');
    var k = { x: 0, y: 1, z: 2 }[a];
    if (k === undefined) { k = 2; }
    var lo = boxMin.getComponent(k), hi = boxMax.getComponent(k);
    var value = lo + clip.t * (hi - lo);
    var normal = new THREE.Vector3(0, 0, 0);
    normal.setComponent(k, negative ? 1 : -1);
    // three.js cuts away where normal . x + constant < 0.
    plane.normal.copy(normal);
    plane.constant = negative ? -value : value;
    renderer.clippingPlanes = clip.on ? [plane] : [];
  }

  function render() { renderer.render(scene, camera); }
  controls.addEventListener('change', render);
  window.addEventListener('resize', function () {
    setProjection();
    renderer.setSize(window.innerWidth, window.innerHeight);
    render();
  });

  // ---- panel
  function el(tag, attrs, children) {
    var e = document.createElement(tag);
    Object.keys(attrs || {}).forEach(function (k) {
      if (k === 'text') e.textContent = attrs[k]; else e.setAttribute(k, attrs[k]);
    });
    (children || []).forEach(function (c) { e.appendChild(c); });
    return e;
  }
  function fmt(x) {
    if (x === 0) return '0';
    var a = Math.abs(x);
    return a >= 1e4 || a < 1e-3 ? x.toExponential(2) : x.toPrecision(3);
  }
  function swatch(colour) {
    var s = el('span', { class: 'swatch' });
    s.style.background = typeof colour === 'string' ? colour : '#' + colour.getHexString();
    return s;
  }
  var panel = document.getElementById('panel');
  function buildPanel() {
    panel.innerHTML = '';
    panel.appendChild(el('h1', { text: data.title || 'implicitfit view' }));
    panel.appendChild(el('h2', { text: 'Layers' }));
    layers.forEach(function (entry) {
      var L = entry.data;
      var box = el('input', { type: 'checkbox' });
      box.checked = entry.object.visible;
      box.addEventListener('change', function () {
        entry.object.visible = box.checked; buildPanel(); render();
      });
      var row = el('div', {}, [box]);
      if (L.type === 'mesh') row.appendChild(swatch(entry.colour));
      row.appendChild(document.createTextNode(' ' + L.name + ' \u2014 ' +
        (L.type === 'points' ? L.count.toLocaleString('en') + ' points'
                             : L.triangle_count.toLocaleString('en') + ' triangles') +
        (L.note ? ' (' + L.note + ')' : '')));
      if (L.type === 'points' && entry.modes.length > 1) {
        var select = el('select', {});
        entry.modes.forEach(function (m) {
          var o = el('option', { value: m, text: m });
          if (m === entry.mode) o.selected = true;
          select.appendChild(o);
        });
        select.addEventListener('change', function () {
          entry.mode = select.value; colourPoints(entry); buildPanel(); render();
        });
        row.appendChild(document.createTextNode(' '));
        row.appendChild(select);
      }
      panel.appendChild(row);
    });
    if (layers.some(function (e) { return e.data.type === 'mesh'; }))
      panel.appendChild(el('div', { class: 'note' }, [swatch(INSIDE), document.createTextNode(
        ' inside of a surface (its back faces), seen through the clipping plane or an open edge')]));
    // Clipping plane.
    panel.appendChild(el('h2', { text: 'Clipping plane' }));
    var on = el('input', { type: 'checkbox' });
    on.checked = clip.on;
    var axis = el('select', {});
    ['x', 'y', 'z', '-x', '-y', '-z'].forEach(function (a) {
      var o = el('option', { value: a, text: a });
      if (a === clip.axis) o.selected = true;
      axis.appendChild(o);
    });
    var slider = el('input', { type: 'range', min: '0', max: '1000', value: String(clip.t * 1000) });
    function update() {
      clip.on = on.checked; clip.axis = axis.value; clip.t = Number(slider.value) / 1000;
      applyClip(); render();
    }
    [on, axis].forEach(function (c) { c.addEventListener('change', update); });
    slider.addEventListener('input', update);
    panel.appendChild(el('div', {}, [on, document.createTextNode(' across '), axis, slider]));
    // Legends of the visible point layers.
    layers.forEach(function (entry) {
      if (entry.data.type !== 'points' || !entry.object.visible) return;
      if (entry.mode === 'primitive') panel.appendChild(primitiveLegend(entry));
      if (entry.mode === 'residual') panel.appendChild(residualLegend(entry));
    });
    if (data.notes) data.notes.forEach(function (n) {  // long ones cut, whole on hover
      var note = el('div', { class: 'note', text: n.length > 180 ? n.slice(0, 177) + '\u2026' : n });
      note.title = n;
      panel.appendChild(note);
    });
    panel.appendChild(el('div', { class: 'note', text:
      'drag: orbit \u00b7 wheel: zoom \u00b7 right-drag: pan' }));
  }

  function primitiveLegend(entry) {
    var L = entry.data, div = el('div', {});
    div.appendChild(el('h2', { text: (L.legend_title || 'Primitives') + ' \u2014 ' + L.name }));
    var showParams = opts.params === '1';
    var heads = ['', 'name', 'kind', 'points', 'RMS'].concat(showParams ? ['parameters'] : []);
    var table = el('table', {}, [el('tr', {}, heads.map(function (t) {
      return el('th', { text: t });
    }))]);
    var legend = L.legend || [];
    var count = legend.length;
    if (!count) {  // labels without a scene: one row per label seen
      var seen = {};
      for (var i = 0; i < entry.labels.length; ++i) if (entry.labels[i] >= 0) seen[entry.labels[i]] = 1;
      count = Object.keys(seen).reduce(function (m, k) { return Math.max(m, Number(k) + 1); }, 0);
    }
    for (var k = 0; k < count; ++k) {
      var p = legend[k] || { name: 'label ' + k };
      var cells = [
        el('td', {}, [swatch(primitiveColour(k))]), el('td', { text: p.name || '' }),
        el('td', { text: p.kind || '' }),
        el('td', { class: 'num', text: p.points !== undefined ? String(p.points) : '' }),
        el('td', { class: 'num', text: p.rms !== undefined ? fmt(p.rms) : '' })];
      if (showParams) cells.push(el('td', { class: 'params', text: p.parameters || '' }));
      var row = el('tr', {}, cells);
      if (p.parameters) row.title = p.parameters;  // shown on hover
      table.appendChild(row);
    }
    var un = 0;
    for (var j = 0; j < entry.labels.length; ++j) un += entry.labels[j] < 0;
    if (un) table.appendChild(el('tr', {}, [el('td', {}, [swatch(UNASSIGNED)]),
      el('td', { text: 'none' }), el('td', { text: 'unassigned' }),
      el('td', { class: 'num', text: String(un) }), el('td', {}), el('td', {})]));
    div.appendChild(table);
    var paramsBox = el('input', { type: 'checkbox' });
    paramsBox.checked = showParams;
    paramsBox.addEventListener('change', function () {
      opts.params = paramsBox.checked ? '1' : '0'; buildPanel(); render();
    });
    div.appendChild(el('label', { class: 'note' }, [paramsBox, document.createTextNode(' parameters')]));
    return div;
  }

  function residualLegend(entry) {
    var L = entry.data, s = entry.scale;
    var div = el('div', {});
    div.appendChild(el('h2', { text: (L.residual_title || 'Residual f') + ' \u2014 ' + L.name }));
    var bar = el('div', { class: 'bar' });
    bar.style.background = 'linear-gradient(to right, #' + RESIDUAL_STOPS[0].getHexString() +
                           ', #' + RESIDUAL_STOPS[1].getHexString() + ', #' +
                           RESIDUAL_STOPS[2].getHexString() + ')';
    div.appendChild(bar);
    div.appendChild(el('div', { class: 'scale' }, [el('span', { text: '\u2264 ' + fmt(-s) }),
      el('span', { text: '0' }), el('span', { text: '\u2265 ' + fmt(s) })]));
    div.appendChild(el('div', { class: 'note', text:
      'f < 0 inside (blue), f > 0 outside (red), in the cloud\u2019s units' +
      (L.residual_note ? '; ' + L.residual_note : '') }));
    return div;
  }

  var toggle = document.getElementById('toggle');
  toggle.addEventListener('click', function () {
    panel.style.display = panel.style.display === 'none' ? '' : 'none';
    panelWidth = panel.style.display === 'none' ? 0 : panel.offsetWidth + 16;
    setProjection();
    render();
  });
  if (opts.ui === '0') { panel.style.display = 'none'; toggle.style.display = 'none'; }

  applyClip();
  buildPanel();
  if (opts.ui !== '0') panelWidth = panel.offsetWidth + 16;
  placeCamera();
  render();
  document.body.setAttribute('data-rendered', '1');
})();

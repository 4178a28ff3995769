// The 3D page of `kerf export part.nc -o part.html` (viewer/src/export/part_page.cpp writes the data
// this reads). Everything from the program is put into the page as text (textContent), never as
// markup; no handler is built from the data.
//
// For tests and benchmarks the page keeps its state in window.kerf: selectedLine, selectedMove,
// drawnRoles (the roles of the construction's marks on show), select(line), step(n), orbit(frames)
// (a full turn in that many frames: resolves to {frames, ms}), project(x, y, z) (a point of the part
// in page pixels), shownTriangles(), lineOfMove(m); <html data-ready="1"> once drawn.
'use strict';
(function () {
  const data = JSON.parse(document.getElementById('kerf-data').textContent);
  const LINE_HEIGHT = 18; // px: #lines > div in part_page.css

  // ---- the data's arrays ----
  function bytes(b64) {
    const s = atob(b64 || '');
    const a = new Uint8Array(s.length);
    for (let i = 0; i < s.length; ++i) a[i] = s.charCodeAt(i);
    return a.buffer;
  }
  const f32 = (b) => new Float32Array(bytes(b));
  const u32 = (b) => new Uint32Array(bytes(b));
  const u8 = (b) => new Uint8Array(bytes(b));
  const rgb = (abgr) => [(abgr & 255) / 255, ((abgr >>> 8) & 255) / 255, ((abgr >>> 16) & 255) / 255];
  const css = (abgr) => 'rgb(' + (abgr & 255) + ',' + ((abgr >>> 8) & 255) + ',' + ((abgr >>> 16) & 255) + ')';

  const sceneData = data.scene;
  const moveLine = u32(data.program.moveLine);
  const movePass = u8(data.movePass);
  const moveDeviation = data.moveDeviation ? f32(data.moveDeviation) : null;
  const lines = data.program.lines;
  const ramp = sceneData.colours.ramp.map(rgb);
  const passColours = sceneData.colours.passes.map(rgb);
  const rampAt = (x) => ramp[Math.round(Math.min(Math.max(x, 0), 1) * (ramp.length - 1))];

  const firstMoveOfLine = new Map();
  for (let m = 0; m < moveLine.length; ++m) if (!firstMoveOfLine.has(moveLine[m])) firstMoveOfLine.set(moveLine[m], m);
  const blockLines = Array.from(firstMoveOfLine.keys()).filter((l) => l > 0).sort((a, b) => a - b);
  const constructions = data.constructions.blocks;
  const constructionOfLine = new Map(constructions.map((c) => [c.line, c]));
  const findingsOfLine = new Map();
  data.findings.forEach((f) => {
    if (f.line && (!findingsOfLine.has(f.line) || f.severity === 'error')) findingsOfLine.set(f.line, f.severity);
  });

  // ---- the 3D scene ----
  const canvas = document.getElementById('canvas');
  const renderer = new THREE.WebGLRenderer({ canvas: canvas, antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0xffffff, 1);
  const scene = new THREE.Scene();
  const camera = new THREE.OrthographicCamera(-1, 1, 1, -1, -1e6, 1e6);
  camera.up.set(0, 0, 1);
  scene.add(new THREE.AmbientLight(0xffffff, 0.45));
  const light = new THREE.DirectionalLight(0xffffff, 0.65);
  light.position.set(-0.45, 0.6, 0.65);
  camera.add(light);
  scene.add(camera);

  const lo = new THREE.Vector3().fromArray(sceneData.boundsMin);
  const hi = new THREE.Vector3().fromArray(sceneData.boundsMax);
  const centre = lo.clone().add(hi).multiplyScalar(0.5);
  const radius = Math.max(hi.clone().sub(lo).length() / 2, 1e-3);

  const surfaceData = sceneData.surface;
  const surfaceMove = u32(surfaceData.move);
  const surfaceSlope = f32(surfaceData.slope);
  const surfaceIndex = u32(surfaceData.index);
  const surfaceGeometry = new THREE.BufferGeometry();
  surfaceGeometry.setAttribute('position', new THREE.BufferAttribute(f32(surfaceData.positions), 3));
  surfaceGeometry.setAttribute('color', new THREE.BufferAttribute(new Float32Array(surfaceMove.length * 3), 3));
  surfaceGeometry.setIndex(new THREE.BufferAttribute(surfaceIndex, 1));
  surfaceGeometry.computeVertexNormals();
  const surface = new THREE.Mesh(
    surfaceGeometry,
    new THREE.MeshLambertMaterial({ vertexColors: THREE.VertexColors, side: THREE.DoubleSide,
                                    polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 }));
  scene.add(surface);

  // Line sets: each keeps its vertices by move (moveFirst) so hidden passes can be left out.
  // A line set of the data (vertex pairs, ABGR colours) as line segments; dashed ones measure their
  // length for the dashes; an overlay (the construction) is drawn over the part.
  function lineObject(d, dashed, overlay) {
    const colours = u32(d.colours);
    const colourArray = new Float32Array(colours.length * 3);
    colours.forEach((c, i) => colourArray.set(rgb(c), 3 * i));
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(f32(d.positions), 3));
    g.setAttribute('color', new THREE.BufferAttribute(colourArray, 3));
    const style = { vertexColors: THREE.VertexColors, depthTest: !overlay };
    const material = dashed
      ? new THREE.LineDashedMaterial(Object.assign(style, overlay ? { dashSize: radius / 50, gapSize: radius / 70 }
                                                                    : { dashSize: radius / 60, gapSize: radius / 80 }))
      : new THREE.LineBasicMaterial(style);
    const object = new THREE.LineSegments(g, material);
    if (dashed) object.computeLineDistances();
    if (overlay) object.renderOrder = 3;
    return object;
  }

  const lineSets = {};
  for (const name of Object.keys(sceneData.lines)) {
    const d = sceneData.lines[name];
    const object = lineObject(d, name === 'reference', false);
    lineSets[name] = { object: object, moveFirst: u32(d.moveFirst) };
    scene.add(object);
  }

  // The findings' markers, and the one of the finding clicked.
  function pointsObject(list, size) {
    const g = new THREE.BufferGeometry();
    const positions = new Float32Array(list.length * 3), colours = new Float32Array(list.length * 3);
    list.forEach((p, i) => {
      positions.set(p.p, 3 * i);
      colours.set(p.colour, 3 * i);
    });
    g.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    g.setAttribute('color', new THREE.BufferAttribute(colours, 3));
    return new THREE.Points(g, new THREE.PointsMaterial({ size: size, sizeAttenuation: false,
                                                            vertexColors: THREE.VertexColors, depthTest: false }));
  }
  const severityColour = { error: [0.85, 0.1, 0.1], warning: [0.95, 0.6, 0.05], note: [0.2, 0.45, 0.85] };
  const markers = pointsObject(data.findings.filter((f) => f.point).map((f) => ({ p: f.point,
                                                                                  colour: severityColour[f.severity] })), 9);
  markers.renderOrder = 2;
  scene.add(markers);
  let findingMarker = null;

  // ---- colours and hidden passes ----
  let colourBy = data.colourBy;
  function colourSurface() {
    const colours = surfaceGeometry.getAttribute('color');
    const [s0, s1] = sceneData.slope;
    const span = Math.max(s1 - s0, 1e-6);
    const plain = [0.72, 0.78, 0.86], none = [0.62, 0.63, 0.66];
    for (let v = 0; v < surfaceMove.length; ++v) {
      let c = plain;
      const move = surfaceMove[v];
      if (colourBy === 'slope') c = rampAt((surfaceSlope[v] - s0) / span);
      else if (colourBy === 'pass') c = movePass[move] > 0 ? passColours[(movePass[move] - 1) % passColours.length] : none;
      else if (colourBy === 'deviation' && moveDeviation) {
        const d = moveDeviation[move];
        c = Number.isNaN(d) ? none : rampAt(d / Math.max(data.deviationScale, 1e-9));
      }
      colours.setXYZ(v, c[0], c[1], c[2]);
    }
    colours.needsUpdate = true;
    if (lineSets.deviation) lineSets.deviation.object.visible = colourBy === 'deviation';
    document.documentElement.dataset.colourBy = colourBy;
    requestDraw();
  }

  const hiddenMoves = new Uint8Array(moveLine.length);
  function applyHidden() {
    const shown = [];
    for (let t = 0; t < surfaceIndex.length; t += 3)
      if (!hiddenMoves[surfaceMove[surfaceIndex[t]]]) shown.push(surfaceIndex[t], surfaceIndex[t + 1], surfaceIndex[t + 2]);
    surfaceGeometry.setIndex(new THREE.BufferAttribute(new Uint32Array(shown), 1));
    for (const set of Object.values(lineSets)) {
      if (set.moveFirst.length !== moveLine.length + 1) continue; // not kept by move
      const index = [];
      for (let m = 0; m < moveLine.length; ++m)
        if (!hiddenMoves[m]) for (let v = set.moveFirst[m]; v < set.moveFirst[m + 1]; ++v) index.push(v);
      set.object.geometry.setIndex(index);
    }
    requestDraw();
  }

  // ---- camera ----
  const controls = new THREE.OrbitControls(camera, canvas);
  controls.enableKeys = false;
  controls.addEventListener('change', () => requestDraw());
  const views = {
    top: [0, -1e-4, 1], front: [0, -1, 0], side: [1, 0, 0], iso: [Math.SQRT1_2, -Math.SQRT1_2, Math.SQRT1_2],
  };
  // Frames the sphere (at, r): the view's direction kept, or the named view's.
  function frame(at, r, view) {
    const w = canvas.clientWidth || 1, h = canvas.clientHeight || 1;
    const aspect = w / h;
    const half = r * 1.1;
    camera.left = -half * Math.max(aspect, 1);
    camera.right = half * Math.max(aspect, 1);
    camera.top = half / Math.min(aspect, 1);
    camera.bottom = -half / Math.min(aspect, 1);
    camera.zoom = 1;
    const dir = view ? new THREE.Vector3().fromArray(views[view]).normalize()
                     : camera.position.clone().sub(controls.target).normalize();
    camera.position.copy(at).addScaledVector(dir, Math.max(r, radius) * 4);
    controls.target.copy(at);
    camera.updateProjectionMatrix();
    controls.update();
    requestDraw();
  }
  const fit = (view) => frame(centre, radius, view);

  function resize() {
    const w = canvas.clientWidth, h = canvas.clientHeight;
    renderer.setSize(w, h, false);
    const aspect = w / Math.max(h, 1);
    const half = (camera.top - camera.bottom) / 2;
    camera.left = -half * aspect;
    camera.right = half * aspect;
    camera.updateProjectionMatrix();
    requestDraw();
  }

  // ---- the construction and the selected move ----
  const construction = new THREE.Group();
  construction.renderOrder = 3;
  scene.add(construction);
  const highlight = new THREE.Group();
  scene.add(highlight);
  const labelLayer = document.getElementById('labels');
  let labels = [];

  function clearGroup(group) {
    for (const child of group.children.slice()) {
      group.remove(child);
      child.geometry.dispose();
      child.material.dispose();
    }
  }

  function drawConstruction(c) {
    clearGroup(construction);
    labels.forEach((l) => l.element.remove());
    labels = [];
    window.kerf.drawnRoles = [];
    if (!c) return;
    for (const [d, dashed] of [[c.lines, false], [c.dashed, true]])
      if (d.colours) construction.add(lineObject(d, dashed, true));
    if (c.points.length) construction.add(pointsObject(c.points.map((p) => ({ p: p.p, colour: rgb(p.colour) })), 8));
    for (const l of c.labels) {
      if (!l.label) continue;
      const element = document.createElement('span');
      element.textContent = l.label;
      element.style.color = css(l.colour);
      labelLayer.appendChild(element);
      labels.push({ element: element, at: new THREE.Vector3().fromArray(l.p) });
    }
    window.kerf.drawnRoles = c.roles.slice();
  }

  function highlightMove(move) {
    clearGroup(highlight);
    if (move === null) return;
    for (const name of ['lower', 'upper']) {
      const set = lineSets[name];
      if (!set || set.moveFirst.length !== moveLine.length + 1) continue;
      const a = set.moveFirst[move], b = set.moveFirst[move + 1];
      if (b <= a) continue;
      const g = new THREE.BufferGeometry();
      const positions = set.object.geometry.getAttribute('position').array.slice(3 * a, 3 * b);
      g.setAttribute('position', new THREE.BufferAttribute(positions, 3));
      const object = new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: 0xd000d0, depthTest: false }));
      object.renderOrder = 4;
      highlight.add(object);
    }
  }

  // ---- panels ----
  function element(tag, text, className) {
    const e = document.createElement(tag);
    if (text !== undefined) e.textContent = text;
    if (className) e.className = className;
    return e;
  }

  function showConstructionText(line, c) {
    const panel = document.getElementById('construction');
    panel.replaceChildren();
    if (!line) {
      panel.appendChild(element('p', 'Click a line of the program or the part; Up and Down step block by block.'));
      return;
    }
    if (!c) {
      const text = firstMoveOfLine.has(line)
        ? 'This page carries the constructions of the first ' + constructions.length +
          ' blocks; kerf render FILE --explain-line ' + line + ' draws this one.'
        : 'No move is programmed on line ' + line + '.';
      panel.appendChild(element('p', text));
      return;
    }
    panel.appendChild(element('p', 'line ' + c.line + ': ' + c.block, 'block'));
    if (c.pass) panel.appendChild(element('p', c.pass));
    const key = element('ul', undefined, 'key');
    c.key.forEach((k) => key.appendChild(element('li', k)));
    panel.appendChild(key);
    const words = element('dl');
    for (const [word, sets] of c.words) {
      words.appendChild(element('dt', word));
      words.appendChild(element('dd', sets));
    }
    panel.appendChild(words);
    const modes = element('ul', undefined, 'modes');
    c.modes.forEach((m) => modes.appendChild(element('li', data.constructions.sentences[m])));
    panel.appendChild(modes);
  }

  // The program's text, drawn only where it is seen (a program can have a million lines).
  const textPanel = document.getElementById('text');
  const linesBox = document.getElementById('lines');
  linesBox.style.height = lines.length * LINE_HEIGHT + 'px';
  function drawText() {
    const first = Math.max(0, Math.floor(textPanel.scrollTop / LINE_HEIGHT) - 5);
    const last = Math.min(lines.length, first + Math.ceil(textPanel.clientHeight / LINE_HEIGHT) + 10);
    linesBox.replaceChildren();
    for (let i = first; i < last; ++i) {
      const line = i + 1;
      const row = element('div');
      row.style.top = i * LINE_HEIGHT + 'px';
      row.dataset.line = line;
      if (firstMoveOfLine.has(line)) row.classList.add('block');
      if (findingsOfLine.has(line)) row.classList.add(findingsOfLine.get(line));
      if (line === window.kerf.selectedLine) row.classList.add('selected');
      row.appendChild(element('span', String(line), 'no'));
      row.appendChild(element('span', lines[i]));
      linesBox.appendChild(row);
    }
  }
  textPanel.addEventListener('scroll', drawText);
  linesBox.addEventListener('click', (event) => {
    const row = event.target.closest('div[data-line]');
    if (row) select(Number(row.dataset.line));
  });

  // Selects a line's block; `framed`: the view frames its construction, as the window frames a
  // block stepped to (not when the block was picked on the part: the view stays where it was).
  function select(line, framed = true) {
    const move = firstMoveOfLine.has(line) ? firstMoveOfLine.get(line) : null;
    window.kerf.selectedLine = line;
    window.kerf.selectedMove = move;
    document.documentElement.dataset.selectedLine = line;
    document.documentElement.dataset.selectedMove = move === null ? '' : move;
    const c = constructionOfLine.get(line) || null;
    drawConstruction(c);
    showConstructionText(line, c);
    highlightMove(move);
    if (framed && construction.children.length) {
      const box = new THREE.Box3().setFromObject(construction);
      const sphere = box.getBoundingSphere(new THREE.Sphere());
      if (Number.isFinite(sphere.radius) && sphere.radius > 0) frame(sphere.center, sphere.radius * 1.15, null);
    }
    const y = (line - 1) * LINE_HEIGHT;
    if (y < textPanel.scrollTop || y > textPanel.scrollTop + textPanel.clientHeight - 2 * LINE_HEIGHT)
      textPanel.scrollTop = Math.max(0, y - textPanel.clientHeight / 3);
    drawText();
    requestDraw();
  }

  function step(n) {
    if (blockLines.length === 0) return;
    const at = window.kerf.selectedLine;
    let k;
    if (!at) k = n > 0 ? 0 : blockLines.length - 1;
    else {
      k = blockLines.findIndex((l) => l >= at);
      if (k < 0) k = blockLines.length;
      k = n > 0 ? (blockLines[k] === at ? k + 1 : k) : k - 1;
    }
    select(blockLines[Math.min(Math.max(k, 0), blockLines.length - 1)]);
  }
  document.addEventListener('keydown', (event) => {
    if (event.key === 'ArrowDown' || event.key === 'ArrowUp') {
      event.preventDefault();
      step(event.key === 'ArrowDown' ? 1 : -1);
    }
  });

  // A click on the part (not a drag) selects the block of the move under it.
  let downAt = null;
  canvas.addEventListener('pointerdown', (event) => { downAt = [event.clientX, event.clientY]; });
  canvas.addEventListener('pointerup', (event) => {
    if (!downAt || Math.hypot(event.clientX - downAt[0], event.clientY - downAt[1]) > 4) return;
    const box = canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(((event.clientX - box.left) / box.width) * 2 - 1,
                                  -((event.clientY - box.top) / box.height) * 2 + 1);
    const ray = new THREE.Raycaster();
    ray.setFromCamera(ndc, camera);
    const hit = ray.intersectObject(surface)[0];
    if (hit) select(moveLine[surfaceMove[hit.face.a]], false);
  });

  function fillPanels() {
    const errors = data.findings.filter((f) => f.severity === 'error').length;
    const warnings = data.findings.filter((f) => f.severity === 'warning').length;
    document.getElementById('subtitle').textContent = data.dialect + ' | ' + moveLine.length + ' moves | ' +
      errors + (errors === 1 ? ' error, ' : ' errors, ') + warnings + (warnings === 1 ? ' warning' : ' warnings');
    document.getElementById('size').textContent = sceneData.size;
    const findings = document.getElementById('findings');
    if (data.findings.length === 0) findings.appendChild(element('li', 'none'));
    data.findings.forEach((f) => {
      const item = element('li', undefined, f.severity);
      item.appendChild(element('pre', f.text));
      item.addEventListener('click', () => {
        if (f.line) select(f.line);
        if (findingMarker) scene.remove(findingMarker);
        findingMarker = f.point ? pointsObject([{ p: f.point, colour: severityColour[f.severity] }], 18) : null;
        if (findingMarker) scene.add(findingMarker);
        requestDraw();
      });
      findings.appendChild(item);
    });
    const passes = document.getElementById('passes');
    if (data.passes.length === 0) passes.appendChild(element('li', 'none found'));
    data.passes.forEach((p) => {
      const item = element('li');
      const label = element('label');
      const box = element('input');
      box.type = 'checkbox';
      box.checked = true;
      box.addEventListener('change', () => {
        for (let m = p.first; m < p.end; ++m) hiddenMoves[m] = box.checked ? 0 : 1;
        applyHidden();
      });
      const swatch = element('span', '', 'swatch');
      swatch.style.background = css(sceneData.colours.passes[(p.pass - 1) % sceneData.colours.passes.length]);
      label.append(box, swatch, element('span', p.name + ' (lines ' + p.lines[0] + '–' + p.lines[1] + ')'));
      item.appendChild(label);
      passes.appendChild(item);
    });
    fillTools();
  }

  function fillTools() {
    const tools = document.getElementById('tools');
    for (const view of ['top', 'front', 'side', 'iso']) {
      const b = element('button', view);
      b.addEventListener('click', () => fit(view));
      tools.appendChild(b);
    }
    const fitButton = element('button', 'fit');
    fitButton.addEventListener('click', () => fit(null));
    tools.appendChild(fitButton);
    const choice = element('select');
    choice.setAttribute('aria-label', 'colour by');
    for (const mode of ['plain', 'slope', 'pass', 'deviation']) {
      if (mode === 'deviation' && !moveDeviation) continue;
      const o = element('option', 'colour: ' + mode);
      o.value = mode;
      choice.appendChild(o);
    }
    choice.value = colourBy;
    choice.addEventListener('change', () => { colourBy = choice.value; colourSurface(); });
    tools.appendChild(choice);
    for (const name of ['rapids', 'generators']) {
      if (!lineSets[name]) continue;
      const label = element('label');
      const box = element('input');
      box.type = 'checkbox';
      box.checked = true;
      box.addEventListener('change', () => { lineSets[name].object.visible = box.checked; requestDraw(); });
      label.append(box, element('span', name));
      tools.appendChild(label);
    }
  }

  // ---- drawing ----
  let drawPending = false;
  function draw() {
    drawPending = false;
    renderer.render(scene, camera);
    placeLabels();
  }

  // Each label beside its mark, in the first of four places that covers no label placed before it;
  // else hidden (the side panel lists them all), as kerf render places them.
  function placeLabels() {
    const w = canvas.clientWidth, h = canvas.clientHeight;
    const placed = [];
    const overlaps = (r) => placed.some((q) => r.x < q.x + q.w && q.x < r.x + r.w && r.y < q.y + q.h && q.y < r.y + r.h);
    for (const l of labels) {
      const p = l.at.clone().project(camera);
      const x = ((p.x + 1) / 2) * w, y = ((1 - p.y) / 2) * h;
      const lw = l.element.offsetWidth, lh = l.element.offsetHeight;
      const tries = [[4, -lh - 2], [4, 2], [-lw - 4, -lh - 2], [-lw - 4, 2]];
      const spot = tries.map(([dx, dy]) => ({ x: x + dx, y: y + dy, w: lw, h: lh })).find((r) => !overlaps(r));
      l.element.style.visibility = spot ? 'visible' : 'hidden';
      if (!spot) continue;
      placed.push(spot);
      l.element.style.transform = 'translate(' + spot.x + 'px,' + spot.y + 'px)';
    }
  }
  function requestDraw() {
    if (drawPending) return;
    drawPending = true;
    requestAnimationFrame(draw);
  }

  // A full turn about the part's vertical axis in `frames` frames, each drawn: what a scripted orbit
  // costs (tests/bench/compare.sh).
  function orbit(frames) {
    return new Promise((resolve) => {
      const start = performance.now();
      const offset = camera.position.clone().sub(controls.target);
      let k = 0;
      function next() {
        if (k === frames) {
          resolve({ frames: frames, ms: performance.now() - start });
          return;
        }
        offset.applyAxisAngle(new THREE.Vector3(0, 0, 1), (2 * Math.PI) / frames);
        camera.position.copy(controls.target).add(offset);
        camera.lookAt(controls.target);
        renderer.render(scene, camera);
        ++k;
        requestAnimationFrame(next);
      }
      requestAnimationFrame(next);
    });
  }

  // Where a point of the part is on the page (CSS pixels): a test clicks there.
  function project(x, y, z) {
    camera.updateMatrixWorld();
    const p = new THREE.Vector3(x, y, z).project(camera);
    const box = canvas.getBoundingClientRect();
    return { x: box.left + ((p.x + 1) / 2) * box.width, y: box.top + ((1 - p.y) / 2) * box.height };
  }
  const shownTriangles = () => surfaceGeometry.getIndex().count / 3;
  window.kerf = { selectedLine: null, selectedMove: null, drawnRoles: [], select: select, step: step, orbit: orbit,
                  project: project, shownTriangles: shownTriangles, lineOfMove: (m) => moveLine[m] };
  fillPanels();
  window.addEventListener('resize', resize);
  renderer.setSize(canvas.clientWidth, canvas.clientHeight, false);
  fit('iso');
  colourSurface();
  showConstructionText(null, null);
  drawText();
  requestAnimationFrame(() => {
    draw();
    document.documentElement.dataset.ready = '1';
  });
})();

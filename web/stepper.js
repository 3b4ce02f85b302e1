// mpr step --html: the pass stepper. Plain script, no framework; the data is
// in window.MPR_STEP (passes.js, frames.js, history.js, written by
// cli/step_page.cpp). Formats decoded here are described in
// cli/frame_delta_encoder.hpp and cli/pixel_history_encoder.hpp.
'use strict';
(function () {
  const D = window.MPR_STEP;
  const $ = (id) => document.getElementById(id);
  function fatal(message) {
    document.body.insertAdjacentHTML('afterbegin', '<p class="fatal"></p>');
    document.querySelector('.fatal').textContent = message;
  }
  if (!D || !D.frames || !D.history || !D.history.tiles) {
    fatal('The page data (passes.js, frames.js, history.js) did not load: open index.html from the folder mpr step --html wrote.');
    return;
  }
  if (typeof DecompressionStream === 'undefined') {
    fatal('This browser lacks DecompressionStream (Chrome 80+, Firefox 113+, Safari 16.4+ have it).');
    return;
  }

  const W = D.width, H = D.height, N = D.passes.length, L = D.levels;
  const stencilBits = D.profile.stencil_bits, depthMax = 2 ** D.profile.depth_bits - 1;

  // ---- bytes --------------------------------------------------------------
  function fromBase64(s) {
    const bin = atob(s), out = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; ++i) out[i] = bin.charCodeAt(i);
    return out;
  }
  async function inflate(s) {
    const stream = new Blob([fromBase64(s)]).stream().pipeThrough(new DecompressionStream('deflate'));
    return new Uint8Array(await new Response(stream).arrayBuffer());
  }
  class Reader {
    constructor(bytes) { this.b = bytes; this.i = 0; }
    varint() {  // unsigned LEB128, exact up to 2^53
      let v = 0, scale = 1, byte;
      do { byte = this.b[this.i++]; v += (byte & 0x7f) * scale; scale *= 128; } while (byte & 0x80);
      return v;
    }
    signed() { const v = this.varint(); return v % 2 === 0 ? v / 2 : -(v + 1) / 2; }
  }

  // ---- buffers: frame k is before any call (k = 0) or at the end of pass k - 1
  function emptyFrame() {
    return { colour: new Uint8Array(W * H * 4), depth: new Uint32Array(W * H),
             stencil: new Uint8Array(W * H), accum: new Int16Array(W * H * 4) };
  }
  function cloneFrame(f) {
    return { colour: f.colour.slice(), depth: f.depth.slice(), stencil: f.stencil.slice(), accum: f.accum.slice() };
  }
  // One buffer's runs: element-wise wrapping differences, `size` bytes little-endian each.
  function applyRuns(r, target, perPixel, size) {
    const runs = r.varint();
    let p = 0;
    for (let n = 0; n < runs; ++n) {
      p += r.varint();
      const len = r.varint();
      for (let i = p * perPixel, end = (p + len) * perPixel; i < end; ++i) {
        let d = 0;
        for (let k = 0; k < size; ++k) d += r.b[r.i++] * 2 ** (8 * k);
        target[i] += d;  // typed arrays wrap, which is the encoder's arithmetic
      }
      p += len;
    }
  }
  function applyDelta(frame, bytes) {
    const r = new Reader(bytes);
    applyRuns(r, frame.colour, 4, 1);
    applyRuns(r, frame.depth, 1, 4);
    applyRuns(r, frame.stencil, 1, 1);
    applyRuns(r, frame.accum, 4, 2);
  }
  // Full frames are kept every `keyEvery` frames and for the last few shown.
  const keyEvery = Math.max(8, Math.ceil((N + 1) / 16));
  const keyFrames = new Map(), recent = new Map();
  async function frameAt(k) {
    if (keyFrames.has(k)) return keyFrames.get(k);
    if (recent.has(k)) return recent.get(k);
    let j = k - 1;
    while (j >= 0 && !keyFrames.has(j) && !recent.has(j)) --j;
    const frame = j < 0 ? emptyFrame() : cloneFrame(keyFrames.get(j) || recent.get(j));
    for (let i = j + 1; i <= k; ++i) {
      applyDelta(frame, await inflate(D.frames[i]));
      if (i % keyEvery === 0 && i !== k) keyFrames.set(i, cloneFrame(frame));
    }
    if (k % keyEvery === 0) keyFrames.set(k, frame);
    else {
      recent.set(k, frame);
      if (recent.size > 4) recent.delete(recent.keys().next().value);
    }
    return frame;
  }

  // ---- stencil values: the algorithm's names and a false-colour palette ----
  const levelHues = ['#2ca02c', '#17becf', '#bcbd22', '#e377c2', '#8c564b', '#1f77b4', '#7f7f7f', '#98df8a'];
  function stencilName(v) {
    if (v === L.zero) return 'ZERO: the render area';
    if (v < L.shad_min) return 'level ' + v + ': area of recursion level ' + v;
    if (v === L.shad_min) return 'SHAD_MIN';
    if (v < L.shad_zero) return 'SHAD_ZERO \u2212 ' + (L.shad_zero - v) + ': shadow count \u2212' + (L.shad_zero - v);
    if (v === L.shad_zero) return 'SHAD_ZERO: shadow count 0';
    return 'SHAD_ZERO + ' + (v - L.shad_zero) + ': inside ' + (v - L.shad_zero) + ' shadow volume' + (v - L.shad_zero > 1 ? 's' : '');
  }
  function hsl(h, s, l) {  // CSS hsl() to RGB bytes
    s /= 100; l /= 100;
    const f = (n) => { const k = (n + h / 30) % 12; return Math.round(255 * (l - s * Math.min(l, 1 - l) * Math.max(-1, Math.min(k - 3, 9 - k, 1)))); };
    return [f(0), f(8), f(4)];
  }
  function hexRgb(h) { return [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16)); }
  function stencilColour(v) {
    if (v === L.zero) return [26, 26, 26];
    if (v < L.shad_min) return hexRgb(levelHues[(v - 1) % levelHues.length]);
    if (v === L.shad_min) return hexRgb('#9467bd');
    if (v < L.shad_zero) return hsl(215, 75, Math.max(22, 62 - 6 * (L.shad_zero - v - 1)));
    if (v === L.shad_zero) return hexRgb('#fff3b0');
    const n = v - L.shad_zero;
    return n === 1 ? hexRgb('#ff7f0e') : hsl(0, 78, Math.max(18, 50 - 7 * (n - 2)));
  }
  const palette = [];
  for (let v = 0; v <= L.max; ++v) palette.push(stencilColour(v));
  const css = (rgb) => 'rgb(' + rgb.join(',') + ')';

  // ---- the page's state ----------------------------------------------------
  const passInfo = D.passes.map((p) => splitLabel(p.label));
  let selected = 0, after = true, bit = stencilBits - 1, pixel = null;
  let shownFrame = null;

  // "draw_window level 0 > light 0 > shadow volumes | make_all_shadows(ALWAYS)":
  // a path of routines, then the pseudo-code line after " | ".
  function splitLabel(label) {
    const bar = label.indexOf(' | ');
    const head = bar >= 0 ? label.slice(0, bar) : label;
    const path = head.split(' > ');
    return { groups: path.slice(0, -1), name: path[path.length - 1], pseudo: bar >= 0 ? label.slice(bar + 3) : label };
  }

  // ---- the pass tree -------------------------------------------------------
  const passItems = [];
  function buildTree() {
    const root = document.createElement('ul');
    const stack = [{ name: null, list: root }];
    passInfo.forEach((info, i) => {
      let common = 0;
      while (common < info.groups.length && common + 1 < stack.length && stack[common + 1].name === info.groups[common]) ++common;
      stack.length = common + 1;
      for (let g = common; g < info.groups.length; ++g) {
        const li = document.createElement('li');
        li.className = 'group';
        const details = document.createElement('details');
        details.open = true;
        const summary = document.createElement('summary');
        summary.textContent = info.groups[g];
        const list = document.createElement('ul');
        details.append(summary, list);
        li.append(details);
        stack[stack.length - 1].list.append(li);
        stack.push({ name: info.groups[g], list });
      }
      const li = document.createElement('li');
      li.className = 'pass';
      li.dataset.pass = String(i);
      li.title = D.passes[i].label;
      const num = document.createElement('span');
      num.className = 'num';
      num.textContent = String(i);
      li.append(num, document.createTextNode(info.name));
      li.addEventListener('click', () => select(i));
      stack[stack.length - 1].list.append(li);
      passItems.push(li);
    });
    $('tree').append(root);
  }

  // ---- views -----------------------------------------------------------------
  const canvases = ['colour', 'depth', 'stencil', 'bit', 'accum'].map((name) => {
    const c = $('view-' + name);
    c.width = W;
    c.height = H;
    return c;
  });
  const [cColour, cDepth, cStencil, cBit, cAccum] = canvases;
  // Drawn with putImageData only; willReadFrequently keeps them in memory the tests read.
  const contexts = canvases.map((c) => c.getContext('2d', { willReadFrequently: true }));
  const images = contexts.map((g) => g.createImageData(W, H));

  // Rows are stored from window y = 0 (the bottom); a canvas starts at the top.
  function paint(index, fill) {
    const img = images[index], out = img.data;
    for (let y = 0; y < H; ++y) {
      let o = (H - 1 - y) * W * 4;
      for (let x = 0, p = y * W; x < W; ++x, ++p, o += 4) { fill(p, out, o); out[o + 3] = 255; }
    }
    contexts[index].putImageData(img, 0, 0);
  }
  function drawViews(f) {
    paint(0, (p, out, o) => { out[o] = f.colour[4 * p]; out[o + 1] = f.colour[4 * p + 1]; out[o + 2] = f.colour[4 * p + 2]; });
    let lo = Infinity, hi = -Infinity;
    for (let p = 0; p < W * H; ++p) { const d = f.depth[p]; if (d < depthMax) { if (d < lo) lo = d; if (d > hi) hi = d; } }
    const span = hi > lo ? hi - lo : 1;
    paint(1, (p, out, o) => {
      const d = f.depth[p];
      const g = d >= depthMax ? 0 : Math.round(255 - 200 * (d - lo) / span);
      out[o] = out[o + 1] = out[o + 2] = g;
    });
    $('depth-note').textContent = lo === Infinity ? 'all at the far plane ' + depthMax + ' (black)'
      : lo === hi ? 'all ' + lo + ' (light) or the far plane ' + depthMax + ' (black)'
      : 'near light, far dark: ' + lo + ' to ' + hi + ' stretched; ' + depthMax + ' (far) black';
    paint(2, (p, out, o) => { const c = palette[f.stencil[p]]; out[o] = c[0]; out[o + 1] = c[1]; out[o + 2] = c[2]; });
    paint(3, (p, out, o) => { const on = (f.stencil[p] >> bit) & 1; out[o] = out[o + 1] = out[o + 2] = on ? 250 : 40; });
    const st = stateOf(selected), mask = st && st.stencil;
    $('bit-note').textContent = 'set white; ' + (mask ? ((mask.write_mask >> bit) & 1 ? 'in' : 'not in') +
      ' the pass\'s write mask 0x' + mask.write_mask.toString(16) : '');
    let negative = 0;
    paint(4, (p, out, o) => {
      for (let c = 0; c < 3; ++c) {
        const w = f.accum[4 * p + c];
        if (w < 0) ++negative;
        out[o + c] = Math.round(255 * Math.min(1, Math.max(0, w / 32767)));
      }
    });
    $('accum-note').textContent = 'RGB words / 32767, clamped to 0..1' + (negative ? ' (' + negative + ' negative words shown as 0)' : '');
    drawLegend(f);
  }
  function drawLegend(f) {
    const counts = new Array(L.max + 1).fill(0);
    for (let p = 0; p < W * H; ++p) ++counts[f.stencil[p]];
    const rows = [];
    for (let v = 0; v <= L.max; ++v)
      if (counts[v] || v === L.zero || v === 1 || v === L.shad_min || v === L.shad_zero) rows.push(v);
    const table = $('legend');
    table.textContent = '';
    for (const v of rows) {
      const tr = table.insertRow();
      const sw = document.createElement('span');
      sw.className = 'swatch';
      sw.style.background = css(palette[v]);
      tr.insertCell().append(sw);
      tr.insertCell().textContent = String(v);
      tr.insertCell().textContent = stencilName(v);
      const c = tr.insertCell();
      c.className = 'count';
      c.textContent = counts[v] ? counts[v] + ' px' : '';
    }
  }

  // ---- GL state --------------------------------------------------------------
  const parsedStates = [];
  function stateOf(p) {
    if (parsedStates[p] === undefined) {
      try { parsedStates[p] = JSON.parse(D.passes[p].state); } catch (e) { parsedStates[p] = null; }
    }
    return parsedStates[p];
  }
  const hex = (v) => '0x' + v.toString(16);
  function stateRows(s) {
    if (!s) return [];
    const st = s.stencil, dp = s.depth, bl = s.blend, fog = s.fog;
    const on = (e) => (e ? 'on' : 'off');
    return [
      ['stencil test', on(st.enabled) + ', ' + st.func + ' ref ' + st.ref + ' (' + hex(st.ref) + ')'],
      ['stencil masks', 'value ' + hex(st.value_mask) + ', write ' + hex(st.write_mask)],
      ['stencil ops', 'sfail ' + st.sfail + ', dpfail ' + st.dpfail + ', dppass ' + st.dppass],
      ['depth test', on(dp.enabled) + ', ' + dp.func + ', writes ' + on(dp.write_mask) + ', range [' + dp.range.join(', ') + ']'],
      ['blend', on(bl.enabled) + ', ' + bl.src + ' ' + bl.dst],
      ['fog', on(fog.enabled) + ', ' + fog.mode + ', density ' + fog.density + ', start ' + fog.start + ', end ' + fog.end],
      ['colour mask', s.color_mask.map((m, i) => (m ? 'RGBA'[i] : '-')).join('')],
      ['alpha test', on(s.alpha_test.enabled) + ', ' + s.alpha_test.func + ' ' + s.alpha_test.ref],
      ['cull face', on(s.cull_face.enabled) + ', ' + s.cull_face.mode + ', front ' + s.cull_face.front_face],
      ['lighting', on(s.lighting) + ', ' + s.shade_model],
      ['clip planes', s.clip_planes.map((c, i) => (c ? String(i) : '')).filter(Boolean).join(' ') || 'none'],
      ['viewport', s.viewport.join(' ') + (s.scissor.enabled ? '; scissor ' + s.scissor.box.join(' ') : '')],
    ];
  }
  function showState() {
    const now = stateRows(stateOf(selected)), before = selected > 0 ? stateRows(stateOf(selected - 1)) : [];
    const table = $('state');
    table.textContent = '';
    now.forEach(([name, value], i) => {
      const tr = table.insertRow();
      if (before[i] && before[i][1] !== value) { tr.className = 'changed'; tr.title = 'changed in this pass'; }
      const th = document.createElement('th');
      th.textContent = name;
      tr.append(th);
      tr.insertCell().textContent = value;
    });
    $('state-title').textContent = 'GL state at the end of pass ' + selected + (selected > 0 ? ' (changes marked)' : '');
    $('state-json').textContent = D.passes[selected].state;
  }

  // ---- pixel histories -------------------------------------------------------
  const FIELDS = ['s0', 's1', 'd0', 'dz', 'd1', 'c0', 'c1'];
  const templates = D.history.templates.map((text) => ({ text, fields: FIELDS.filter((f) => text.includes('{' + f + '}')) }));
  const tileSize = D.history.tile, tilesX = Math.ceil(W / tileSize);
  const rgba = (c) => '(' + c.join(',') + ')';
  // The events of one pixel, as {pass, text}. A tile's stream holds its
  // pixels' events in the order they happened (cli/pixel_history_encoder.hpp),
  // so the whole stream is decoded, but only the wanted pixel's lines are
  // worded.
  function pixelEvents(bytes, tx, ty, x, y) {
    const x0 = tx * tileSize, y0 = ty * tileSize, tw = Math.min(tileSize, W - x0);
    const n = tw * Math.min(tileSize, H - y0), want = (y - y0) * tw + (x - x0);
    const S = new Float64Array(n), Dp = new Float64Array(n), C = new Uint8Array(4 * n);
    const lastLine = new Float64Array(n).fill(-1), rank = new Float64Array(n);
    const r = new Reader(bytes), events = [], c1 = new Uint8Array(4);
    let pix = 0, pass = 0, line = 0, dz = 0;
    while (r.i < bytes.length) {
      pix += r.signed();
      const t = templates[r.varint()];
      pass += r.varint();
      line += r.varint();
      const v = pix === want ? { line } : null;
      for (const f of t.fields) {
        if (f === 's0' || f === 's1') { S[pix] += r.signed(); if (v) v[f] = S[pix]; }
        else if (f === 'd0' || f === 'd1') { Dp[pix] += r.signed(); if (v) v[f] = Dp[pix]; }
        else if (f === 'dz') { dz += r.signed(); if (v) v.dz = dz; }
        else if (f === 'c0') {
          for (let k = 0; k < 4; ++k) C[4 * pix + k] += r.b[r.i++];
          if (v) v.c0 = rgba(Array.from(C.subarray(4 * pix, 4 * pix + 4)));
        } else {
          for (let k = 0; k < 4; ++k) { c1[k] += r.b[r.i++]; C[4 * pix + k] = c1[k]; }
          if (v) v.c1 = rgba(Array.from(c1));
        }
      }
      rank[pix] = line === lastLine[pix] ? rank[pix] + 1 : 1;  // a call's fragments at a pixel are consecutive
      lastLine[pix] = line;
      if (v) {
        v.k = rank[pix];
        events.push({ pass, text: t.text.replace(/\{(\w+)\}/g, (m, f) => String(v[f])) });
      }
    }
    return events;
  }
  const tileBytes = new Map(), pixelCache = new Map();
  async function historyOf(x, y) {
    const key = y * W + x;
    if (pixelCache.has(key)) return pixelCache.get(key);
    const tx = Math.floor(x / tileSize), ty = Math.floor(y / tileSize), t = ty * tilesX + tx;
    if (!tileBytes.has(t)) {
      const chunks = await Promise.all(D.history.tiles[t].map(inflate));
      const bytes = new Uint8Array(chunks.reduce((n, c) => n + c.length, 0));
      let at = 0;
      for (const c of chunks) { bytes.set(c, at); at += c.length; }
      if (tileBytes.size >= 8) tileBytes.delete(tileBytes.keys().next().value);
      tileBytes.set(t, bytes);
    }
    const events = pixelEvents(tileBytes.get(t), tx, ty, x, y);
    if (pixelCache.size >= 64) pixelCache.delete(pixelCache.keys().next().value);
    pixelCache.set(key, events);
    return events;
  }
  // As {pass, text} lines, each pass's header before its first line.
  function historyLines(events, last) {
    const lines = [];
    let header = -1;
    for (const e of events) {
      if (e.pass > last) break;
      if (e.pass !== header) { lines.push({ pass: e.pass, text: D.passes[e.pass].header }); header = e.pass; }
      lines.push(e);
    }
    return lines;
  }
  // The text is exactly --pixel's lines; the selected pass's lines are marked
  // and scrolled to.
  function showHistory(lines) {
    const box = $('history');
    box.textContent = '';
    let mark = null;
    lines.forEach((l, i) => {
      const span = document.createElement('span');
      span.textContent = l.text;
      if (l.pass === selected) { span.className = 'current'; mark = mark || span; }
      box.append(span);
      if (i + 1 < lines.length) box.append('\n');
    });
    box.scrollTop = mark ? mark.offsetTop - 4 : box.scrollHeight;  // #history is the offsetParent
  }
  function bits(v) { return v.toString(2).padStart(stencilBits, '0'); }
  // As `mpr step --pixel` words its final line (after "final: ").
  function valueText(s, d, c) {
    return 'stencil ' + s + ' = 0x' + s.toString(16) + ' = 0b' + bits(s) + ', depth ' + d + ', colour ' + rgba(c);
  }
  async function showPixel() {
    document.querySelectorAll('.marker').forEach((m) => { m.style.display = pixel ? 'block' : 'none'; });
    if (!pixel || !shownFrame) return;
    const { x, y } = pixel, p = y * W + x, f = shownFrame;
    const size = Math.max(9, canvases[0].clientWidth / W + 4);
    document.querySelectorAll('.marker').forEach((m) => {
      m.style.width = m.style.height = size + 'px';
      m.style.left = 'calc(' + ((x + 0.5) / W * 100) + '% - ' + size / 2 + 'px)';
      m.style.top = 'calc(' + ((H - 1 - y + 0.5) / H * 100) + '% - ' + size / 2 + 'px)';
    });
    const s = f.stencil[p], c = Array.from(f.colour.slice(4 * p, 4 * p + 4));
    const moment = (after ? 'end' : 'start') + ' of pass ' + selected;
    $('pixel-title').textContent = 'pixel (' + x + ',' + y + ') at the ' + moment;
    $('stencil-big').textContent = 'stencil ' + s + ' = 0x' + s.toString(16) + ' = 0b' + bits(s);
    $('stencil-meaning').textContent = stencilName(s);
    $('pixel-value').textContent = valueText(s, f.depth[p], c);
    const a = Array.from(f.accum.slice(4 * p, 4 * p + 4));
    $('pixel-extra').textContent = 'accumulation words ' + rgba(a) + ' = ' + rgba(a.map((w) => (w / 32767).toFixed(4)));
    const last = after ? selected : selected - 1;
    const recorded = D.history.recorded_passes;
    const events = await historyOf(x, y);
    if (!pixel || pixel.x !== x || pixel.y !== y) return;
    $('history-title').textContent = 'history up to the ' + moment +
      (last < 0 ? ': nothing has run yet' : events.some((e) => e.pass <= last) ? '' : ': nothing reached this pixel');
    showHistory(historyLines(events, Math.min(last, recorded - 1)));
    const note = $('history-note');
    note.textContent = '';
    const command = document.createElement('code');
    command.textContent = D.pixel_command + ' ' + x + ',' + y;
    if (last >= recorded) {
      note.append('This page recorded pixel histories for passes 0 to ' + (recorded - 1) + ' only (the ' +
        D.history.limit_mb + ' MB limit of --history-mb); for the whole history run ', command);
    } else {
      note.append('The same lines as ', command);
    }
    document.body.dataset.pixel = x + ',' + y + ':' + selected + ':' + (after ? 'after' : 'before');
  }

  // ---- selection and rendering ------------------------------------------------
  let request = 0, chain = Promise.resolve();
  function render() {
    const token = ++request;
    $('busy').textContent = 'decoding\u2026';
    chain = chain.then(async () => {
      if (token !== request) return;  // a later request supersedes this one
      const f = await frameAt(after ? selected + 1 : selected);
      if (token !== request) return;
      shownFrame = f;
      drawViews(f);
      await showPixel();
      if (token !== request) return;
      $('busy').textContent = '';
      document.body.dataset.shown = selected + ':' + (after ? 'after' : 'before');
    }).catch((e) => { $('busy').textContent = 'error: ' + e.message; console.error(e); });
  }
  function select(i) {
    selected = Math.max(0, Math.min(N - 1, i));
    passItems.forEach((li, k) => li.classList.toggle('selected', k === selected));
    const li = passItems[selected];
    for (let d = li.parentElement.closest('details'); d; d = d.parentElement.closest('details')) d.open = true;
    li.scrollIntoView({ block: 'nearest' });
    const info = passInfo[selected];
    $('pass-title').textContent = 'pass ' + selected + ' of ' + (N - 1) + ': ' + D.passes[selected].label +
      ' (line ' + D.passes[selected].line + ')';
    $('pass-of').textContent = 'pass ' + selected + ' / ' + (N - 1);
    $('pseudo').textContent = info.pseudo;
    $('errors').textContent = D.passes[selected].errors.map((e) => 'GL error at line ' + e).join('; ');
    showState();
    render();
  }
  function setWhen(isAfter) {
    after = isAfter;
    $('before').setAttribute('aria-pressed', String(!after));
    $('after').setAttribute('aria-pressed', String(after));
    render();
  }
  function pick(canvas, ev) {
    const r = canvas.getBoundingClientRect();
    const x = Math.floor((ev.clientX - r.left) / r.width * W), yTop = Math.floor((ev.clientY - r.top) / r.height * H);
    if (x < 0 || x >= W || yTop < 0 || yTop >= H) return;
    pixel = { x, y: H - 1 - yTop };
    showPixel();
  }

  // ---- start ------------------------------------------------------------------
  $('input').textContent = D.input + ' \u00b7 ' + W + '\u00d7' + H + ' \u00b7 profile ' + D.profile.name;
  document.title = 'mpr step \u00b7 ' + D.input;
  for (let b = stencilBits - 1; b >= 0; --b) {
    const o = document.createElement('option');
    o.value = String(b);
    o.textContent = String(b) + ' (' + (1 << b) + ')';
    $('bit').append(o);
  }
  $('bit').value = String(bit);
  $('bit').addEventListener('change', () => { bit = Number($('bit').value); render(); });
  $('before').addEventListener('click', () => setWhen(false));
  $('after').addEventListener('click', () => setWhen(true));
  canvases.forEach((c) => c.addEventListener('click', (ev) => pick(c, ev)));
  document.addEventListener('keydown', (ev) => {
    if (ev.target instanceof HTMLSelectElement || ev.altKey || ev.ctrlKey || ev.metaKey) return;
    const moves = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] };
    if (ev.shiftKey && moves[ev.key]) {
      if (!pixel) pixel = { x: 0, y: 0 };
      pixel = { x: Math.max(0, Math.min(W - 1, pixel.x + moves[ev.key][0])), y: Math.max(0, Math.min(H - 1, pixel.y + moves[ev.key][1])) };
      showPixel();
    } else if (ev.key === 'ArrowDown' || ev.key === 'j') select(selected + 1);
    else if (ev.key === 'ArrowUp' || ev.key === 'k') select(selected - 1);
    else if (ev.key === 'PageDown') select(selected + 10);
    else if (ev.key === 'PageUp') select(selected - 10);
    else if (ev.key === 'Home') select(0);
    else if (ev.key === 'End') select(N - 1);
    else if (ev.key === 'b') setWhen(!after);
    else if (ev.key === 'z') { $('views').classList.toggle('large'); showPixel(); }
    else if (/^[0-7]$/.test(ev.key) && Number(ev.key) < stencilBits) { bit = Number(ev.key); $('bit').value = ev.key; render(); }
    else return;
    ev.preventDefault();
  });
  window.addEventListener('resize', () => showPixel());
  // Jumps far ahead are quicker with the full frames every keyEvery passes:
  // build them in the background, one at a time between the user's requests.
  function warmUp(k) {
    if (k > N) return;
    chain = chain.then(() => frameAt(k)).then(() => setTimeout(() => warmUp(k + keyEvery), 0));
  }
  buildTree();
  setWhen(true);
  select(0);
  warmUp(keyEvery);
})();

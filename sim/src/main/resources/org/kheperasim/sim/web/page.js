// The replay of one run: RUN describes it, SAMPLES carries its samples (see TapeEncoder).
// The drawing follows the simulator's window (gui/ArenaRenderer, gui/SensorRenderer): same
// colours, same shapes, same fit of the arena into its area.
(function () {
  'use strict';

  // The window's colours (ArenaRenderer, SensorRenderer); a test checks they still agree.
  var C = {
    floor: '#F4F1E8', outside: '#6B6F76', wall: '#3A3F4B', robot: '#2E8B57', cap: '#D03030', lamp: '#F0A000',
    selection: '#1E6FFF', grid: '#E4DFD2', region: '#8090A0', trail: '#1E6FFF', wheel: '#202020',
    gripper: '#505A66', object: '#FF3030', ledOff: '#1E5A38', label: '#202830', prox: '#D43C3C', light: '#E0A800',
    contactMark: '#7A808C', failure: '#B00020'
  };
  var SPEEDS = [0.25, 0.5, 1, 2, 4, 8, 16, 64];
  var M = RUN.model;
  var $ = function (id) { return document.getElementById(id); };

  // Java's Color.darker(): each channel times 0.7, truncated.
  function darker(hex) {
    var v = parseInt(hex.slice(1), 16);
    var r = Math.floor((v >> 16 & 255) * 0.7), g = Math.floor((v >> 8 & 255) * 0.7), b = Math.floor((v & 255) * 0.7);
    return '#' + ((1 << 24) | (r << 16) | (g << 8) | b).toString(16).slice(1);
  }

  // ------------------------------------------------------------------ unpacking the samples

  // Raw deflate (RFC 1951), as java.util.zip.Deflater writes it.
  function inflate(src, size) {
    var out = new Uint8Array(size), op = 0, ip = 0, buf = 0, cnt = 0;
    function bits(n) {
      while (cnt < n) {
        if (ip >= src.length) { throw new Error('the packed samples are cut short'); }
        buf |= src[ip++] << cnt;
        cnt += 8;
      }
      var v = buf & ((1 << n) - 1);
      buf >>>= n;
      cnt -= n;
      return v;
    }
    function table(lengths, n) {
      var count = new Uint16Array(16), sym = new Uint16Array(n), offs = new Uint16Array(16), i;
      for (i = 0; i < n; i++) { count[lengths[i]]++; }
      count[0] = 0;
      for (i = 1; i < 16; i++) { offs[i] = offs[i - 1] + count[i - 1]; }
      for (i = 0; i < n; i++) { if (lengths[i]) { sym[offs[lengths[i]]++] = i; } }
      return { count: count, sym: sym };
    }
    function decode(h) {
      var code = 0, first = 0, index = 0, len, c;
      for (len = 1; len < 16; len++) {
        code |= bits(1);
        c = h.count[len];
        if (code - c < first) { return h.sym[index + (code - first)]; }
        index += c;
        first = (first + c) << 1;
        code <<= 1;
      }
      throw new Error('the packed samples are damaged (no such code)');
    }
    var LB = [3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258];
    var LE = [0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0];
    var DB = [1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769, 1025, 1537, 2049, 3073,
      4097, 6145, 8193, 12289, 16385, 24577];
    var DE = [0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13];
    var ORDER = [16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15];
    function codes(lit, dist) {
      for (;;) {
        var s = decode(lit);
        if (s < 256) {
          out[op++] = s;
        } else if (s === 256) {
          return;
        } else {
          s -= 257;
          if (s >= 29) { throw new Error('the packed samples are damaged (length code)'); }
          var len = LB[s] + bits(LE[s]);
          var d = decode(dist);
          if (d >= 30) { throw new Error('the packed samples are damaged (distance code)'); }
          var back = DB[d] + bits(DE[d]);
          if (back > op || op + len > size) { throw new Error('the packed samples are damaged (distance)'); }
          while (len--) { out[op] = out[op - back]; op++; }
        }
      }
    }
    function dynamic() {
      var nlen = bits(5) + 257, ndist = bits(5) + 1, ncode = bits(4) + 4, i;
      var lengths = new Uint8Array(19);
      for (i = 0; i < ncode; i++) { lengths[ORDER[i]] = bits(3); }
      var lencode = table(lengths, 19);
      var all = new Uint8Array(nlen + ndist);
      i = 0;
      while (i < nlen + ndist) {
        var sym = decode(lencode), value = 0, rep;
        if (sym < 16) { all[i++] = sym; continue; }
        if (sym === 16) {
          if (i === 0) { throw new Error('the packed samples are damaged (repeat)'); }
          value = all[i - 1];
          rep = 3 + bits(2);
        } else {
          rep = sym === 17 ? 3 + bits(3) : 11 + bits(7);
        }
        if (i + rep > nlen + ndist) { throw new Error('the packed samples are damaged (lengths)'); }
        while (rep--) { all[i++] = value; }
      }
      codes(table(all.subarray(0, nlen), nlen), table(all.subarray(nlen), ndist));
    }
    var fixed = null;
    var last;
    do {
      last = bits(1);
      var type = bits(2);
      if (type === 0) {
        buf = 0;
        cnt = 0;
        var n = src[ip] | src[ip + 1] << 8;
        ip += 4;
        if (ip + n > src.length || op + n > size) { throw new Error('the packed samples are damaged (stored block)'); }
        out.set(src.subarray(ip, ip + n), op);
        op += n;
        ip += n;
      } else if (type === 1) {
        if (!fixed) {
          var l = new Uint8Array(288), d = new Uint8Array(30), i;
          for (i = 0; i < 288; i++) { l[i] = i < 144 ? 8 : i < 256 ? 9 : i < 280 ? 7 : 8; }
          for (i = 0; i < 30; i++) { d[i] = 5; }
          fixed = [table(l, 288), table(d, 30)];
        }
        codes(fixed[0], fixed[1]);
      } else if (type === 2) {
        dynamic();
      } else {
        throw new Error('the packed samples are damaged (block type)');
      }
    } while (!last);
    if (op !== size) { throw new Error('the packed samples hold ' + op + ' bytes, not ' + size); }
    return out;
  }

  function unpack() {
    var bin = atob(SAMPLES), src = new Uint8Array(bin.length), i;
    for (i = 0; i < bin.length; i++) { src[i] = bin.charCodeAt(i); }
    var B = inflate(src, RUN.rawBytes), P = 0;
    function uv() {
      var v = 0, mul = 1, c;
      do { c = B[P++]; v += (c & 127) * mul; mul *= 128; } while (c & 128);
      return v;
    }
    function sv() { var z = uv(); return z % 2 ? -(z + 1) / 2 : z / 2; }
    function column(n) {
      var a = new Int32Array(n), acc = 0;
      for (var k = 0; k < n; k++) { acc += sv(); a[k] = acc; }
      return a;
    }
    var names = ['t', 'x', 'y', 'h', 'sl', 'sr', 'el', 'er', 'contact', 'arm', 'fingers', 'obj', 'held'];
    var robots = RUN.robots.map(function (r) {
      var o = { name: r.name, n: r.n, sens: null, m: 0, radius: r.radius || M.robotRadius, mounts: r.mounts || M.sensors };
      names.forEach(function (k) { o[k] = column(r.n); });
      if (r.sensors) {
        o.m = Math.floor((r.n - 1) / RUN.sensorStride) + 1;
        o.sens = [];
        for (var s = 0; s < 16; s++) { o.sens.push(column(o.m)); }
      }
      return o;
    });
    var nc = RUN.capMoves, ct = column(nc), cid = column(nc), caps = [], lastX = {}, lastY = {}, cx = [], cy = [];
    for (i = 0; i < nc; i++) {
      var id = cid[i];
      lastX[id] = (lastX[id] || 0) + sv();
      lastY[id] = (lastY[id] || 0) + sv();
      cx.push(lastX[id]);
      cy.push(lastY[id]);
    }
    for (i = 0; i < nc; i++) {
      var c = cid[i];
      if (!caps[c]) { caps[c] = { t: [], x: [], y: [], held: [] }; }
      caps[c].t.push(ct[i]);
      caps[c].x.push(cx[i]);
      caps[c].y.push(cy[i]);
      caps[c].held.push(sv() - 1);
    }
    if (P !== B.length) { throw new Error('the packed samples do not match their description'); }
    return { robots: robots, caps: caps };
  }

  // ------------------------------------------------------------------ state

  var D, robots, caps, marks = [], startMs, endMs, cur, playing = false, speed = 1, selected = 0, lastFrame = 0;

  /** The last index of a sorted array at or before t (0 when t is before the first). */
  function at(arr, n, t) {
    if (n === 0 || t < arr[0]) { return 0; }
    var lo = 0, hi = n - 1;
    while (lo < hi) {
      var mid = (lo + hi + 1) >> 1;
      if (arr[mid] <= t) { lo = mid; } else { hi = mid - 1; }
    }
    return lo;
  }

  function arenaAt(t) {
    var a = RUN.arenas[0];
    for (var i = 1; i < RUN.arenas.length; i++) { if (RUN.arenas[i].t <= t) { a = RUN.arenas[i]; } }
    return a;
  }

  function fmt(ms) { return (ms / 1000).toFixed(1); }

  function norm(tenthDeg) { var d = (tenthDeg / 10) % 360; if (d > 180) { d -= 360; } if (d <= -180) { d += 360; } return d; }

  function buildMarks() {
    robots.forEach(function (r, ri) {
      for (var i = 0; i < r.n; i++) {
        if (r.contact[i] !== 0 && (i === 0 || r.contact[i - 1] === 0)) {
          marks.push({ t: r.t[i], kind: 'contact', text: (robots.length > 1 ? 'robot ' + ri + ' touches ' : 'contact ')
              + M.contacts[r.contact[i]] });
        }
      }
    });
    caps.forEach(function (c, id) {
      if (!c) { return; }
      for (var e = 1; e < c.t.length; e++) {
        var was = c.held[e - 1], now = c.held[e];
        if (was !== now) {
          marks.push({ t: c.t[e], kind: 'cap', text: now >= 0 ? 'cap ' + id + ' picked up by robot ' + now : 'cap ' + id + ' put down' });
        } else if (now < 0 && c.t[e] - c.t[e - 1] > 1000) {
          marks.push({ t: c.t[e], kind: 'cap', text: 'cap ' + id + ' pushed' });
        }
      }
    });
    RUN.failures.forEach(function (f) {
      var t = f.t === null ? endMs : f.t;
      marks.push({ t: t, kind: 'failure', text: 'robot ' + f.robot + ' ' + words(f.status)
          + (f.t === null ? ' (time not recorded)' : ''), failure: f });
    });
    marks.sort(function (a, b) { return a.t - b.t; });
  }

  function words(status) {
    return { failed: 'threw', hung: 'hung', broke_rule: 'broke a rule', exceeded_memory: 'ran out of memory' }[status] || status;
  }

  // ------------------------------------------------------------------ the arena

  var arenaCanvas = $('arena'), stage = $('stage'), view = null, staticLayer = null, staticKey = '';

  function fit(a, w, h) {
    var margin = 16, s = Math.min((w - 2 * margin) / a.w, (h - 2 * margin) / a.h);
    s = Math.max(0.05, Math.min(40, s));
    var ox = (w - a.w * s) / 2, oy = (h + a.h * s) / 2;
    return {
      s: s, ox: ox, oy: oy,
      x: function (x) { return ox + x * s; },
      y: function (y) { return oy - y * s; },
      len: function (mm) { return mm * s; }
    };
  }

  function circle(g, v, x, y, r) {
    g.beginPath();
    g.arc(v.x(x), v.y(y), v.len(r), 0, 2 * Math.PI);
  }

  function line(g, x1, y1, x2, y2) {
    g.beginPath();
    g.moveTo(x1, y1);
    g.lineTo(x2, y2);
    g.stroke();
  }

  function drawStatic(g, v, w, h, a) {
    g.fillStyle = C.outside;
    g.fillRect(0, 0, w, h);
    var fx = v.x(0), fy = v.y(a.h), fw = v.len(a.w), fh = v.len(a.h);
    g.fillStyle = C.floor;
    g.fillRect(fx, fy, fw, fh);
    if (v.len(100) >= 12) {
      g.strokeStyle = C.grid;
      g.lineWidth = 1;
      g.beginPath();
      for (var gx = 100; gx < a.w; gx += 100) { g.moveTo(v.x(gx), v.y(0)); g.lineTo(v.x(gx), v.y(a.h)); }
      for (var gy = 100; gy < a.h; gy += 100) { g.moveTo(v.x(0), v.y(gy)); g.lineTo(v.x(a.w), v.y(gy)); }
      g.stroke();
    }
    a.regions.forEach(function (r) {
      g.strokeStyle = C.region;
      g.lineWidth = 1;
      g.setLineDash([4, 4]);
      g.strokeRect(v.x(r[1]), v.y(r[4]), v.len(r[3] - r[1]), v.len(r[4] - r[2]));
      g.setLineDash([]);
      if (v.len(r[3] - r[1]) > 60) {
        g.fillStyle = C.region;
        g.font = '10px sans-serif';
        g.fillText(r[0], v.x(r[1]) + 3, v.y(r[4]) + 11);
      }
    });
    // A lamp's glow stays on the floor.
    g.save();
    g.beginPath();
    g.rect(fx, fy, fw, fh);
    g.clip();
    a.lights.forEach(function (l) {
      var cx = v.x(l[0]), cy = v.y(l[1]), radius = Math.max(1, v.len(l[3])), alpha = Math.min(0.55, 0.35 * l[4]);
      var paint = g.createRadialGradient(cx, cy, 0, cx, cy, radius);
      paint.addColorStop(0, 'rgba(255,217,51,' + alpha + ')');
      paint.addColorStop(1, 'rgba(255,217,51,0)');
      g.fillStyle = paint;
      g.beginPath();
      if (l[5] !== null) {
        var from = (l[5] - l[6] / 2) * Math.PI / 180, to = (l[5] + l[6] / 2) * Math.PI / 180;
        g.moveTo(cx, cy);
        g.arc(cx, cy, radius, -from, -to, true);
        g.closePath();
      } else {
        g.arc(cx, cy, radius, 0, 2 * Math.PI);
      }
      g.fill();
    });
    g.restore();
    a.lights.forEach(function (l) {
      circle(g, v, l[0], l[1], l[2]);
      g.fillStyle = C.lamp;
      g.fill();
      g.strokeStyle = darker(C.lamp);
      g.lineWidth = 1;
      g.stroke();
    });
    g.lineCap = 'round';
    g.lineJoin = 'round';
    a.walls.forEach(function (wl) {
      g.strokeStyle = C.wall;
      g.lineWidth = Math.max(1, v.len(wl[4]));
      line(g, v.x(wl[0]), v.y(wl[1]), v.x(wl[2]), v.y(wl[3]));
    });
    g.lineCap = 'butt';
  }

  function drawCap(g, v, x, y, r, held) {
    circle(g, v, x, y, r);
    g.fillStyle = C.cap;
    g.fill();
    g.strokeStyle = held ? '#FFFFFF' : darker(C.cap);
    g.lineWidth = held ? 2 : 1;
    g.stroke();
  }

  function drawRobot(g, v, r, k, showBeams) {
    var x = r.x[k] / 10, y = r.y[k] / 10, h = r.h[k] / 10 * Math.PI / 180, cos = Math.cos(h), sin = Math.sin(h);
    var R = r.radius, side, i;
    if (showBeams && r.sens) {
      var j = Math.min(r.m - 1, Math.floor(k / RUN.sensorStride));
      r.mounts.slice(0, 8).forEach(function (s, si) {
        var sx = x + s[0] * cos - s[1] * sin, sy = y + s[0] * sin + s[1] * cos, a = h + s[2] * Math.PI / 180;
        var val = Math.min(1023, Math.max(0, r.sens[si][j])) / 1023;
        g.strokeStyle = 'rgba(255,26,26,' + (0.15 + 0.7 * val).toFixed(3) + ')';
        g.lineWidth = Math.max(1, v.len(2));
        line(g, v.x(sx), v.y(sy), v.x(sx + 50 * Math.cos(a)), v.y(sy + 50 * Math.sin(a)));
      });
    }
    g.strokeStyle = C.wheel;
    g.lineWidth = Math.max(1, v.len(6));
    g.lineCap = 'butt';
    for (side = -1; side <= 1; side += 2) {
      var wx = x - side * 24 * sin, wy = y + side * 24 * cos;
      line(g, v.x(wx - 10 * cos), v.y(wy - 10 * sin), v.x(wx + 10 * cos), v.y(wy + 10 * sin));
    }
    circle(g, v, x, y, R);
    g.fillStyle = C.robot;
    g.fill();
    g.strokeStyle = darker(darker(C.robot));
    g.lineWidth = 1.5;
    g.stroke();
    // The gripper: the lower the arm, the farther ahead its fingers reach on the floor.
    var lowered = Math.max(0, Math.min(1, (r.arm[k] - M.armUp) / (M.armDown - M.armUp)));
    var reach = 27.5 + 4 + 14 * lowered, spread = r.fingers[k] === M.fingersOpen ? 9 : 3;
    g.strokeStyle = C.gripper;
    g.lineWidth = Math.max(1, v.len(3));
    g.lineCap = 'round';
    for (side = -1; side <= 1; side += 2) {
      line(g, v.x(x + 20 * cos - side * spread * sin), v.y(y + 20 * sin + side * spread * cos),
          v.x(x + reach * cos - side * spread * sin), v.y(y + reach * sin + side * spread * cos));
    }
    if (r.obj[k]) {
      circle(g, v, x + (reach - 3) * cos, y + (reach - 3) * sin, 2.5);
      g.fillStyle = C.object;
      g.fill();
    }
    // The two LEDs (a trace does not record them: drawn off, as the window's replay draws them).
    for (i = 0; i < 2; i++) {
      var lx = -16, ly = i === 0 ? 6 : -6;
      circle(g, v, x + lx * cos - ly * sin, y + lx * sin + ly * cos, 3);
      g.fillStyle = C.ledOff;
      g.fill();
    }
    g.strokeStyle = '#FFFFFF';
    g.lineWidth = Math.max(1.5, v.len(3));
    line(g, v.x(x), v.y(y), v.x(x + R * 0.85 * cos), v.y(y + R * 0.85 * sin));
    g.lineCap = 'butt';
  }

  function drawTrail(g, v, r, k) {
    if (k < 1) { return; }
    g.strokeStyle = C.trail;
    g.lineWidth = 1.5;
    g.lineCap = 'round';
    g.lineJoin = 'round';
    g.beginPath();
    var lx = v.x(r.x[0] / 10), ly = v.y(r.y[0] / 10);
    g.moveTo(lx, ly);
    for (var i = 1; i <= k; i++) {
      var px = v.x(r.x[i] / 10), py = v.y(r.y[i] / 10);
      // Points less than a pixel and a half from the last one drawn add nothing on screen.
      if (Math.abs(px - lx) + Math.abs(py - ly) >= 1.5 || i === k) {
        g.lineTo(px, py);
        lx = px;
        ly = py;
      }
    }
    g.stroke();
    g.lineCap = 'butt';
  }

  function drawArena() {
    var dpr = window.devicePixelRatio || 1, w = stage.clientWidth, h = stage.clientHeight;
    if (!w || !h) { return; }
    if (arenaCanvas.width !== Math.round(w * dpr) || arenaCanvas.height !== Math.round(h * dpr)) {
      arenaCanvas.width = Math.round(w * dpr);
      arenaCanvas.height = Math.round(h * dpr);
    }
    var a = arenaAt(cur);
    view = fit(a, w, h);
    var key = a.t + ' ' + w + 'x' + h + ' ' + dpr;
    if (key !== staticKey) {
      staticLayer = document.createElement('canvas');
      staticLayer.width = arenaCanvas.width;
      staticLayer.height = arenaCanvas.height;
      var sg = staticLayer.getContext('2d');
      sg.setTransform(dpr, 0, 0, dpr, 0, 0);
      drawStatic(sg, view, w, h, a);
      staticKey = key;
    }
    var g = arenaCanvas.getContext('2d');
    g.setTransform(1, 0, 0, 1, 0, 0);
    g.drawImage(staticLayer, 0, 0);
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    var v = view;
    // Caps: where each lay or was held at this moment; where the arena put it before its first move.
    var shown = {};
    caps.forEach(function (c, id) {
      if (!c || c.t[0] > cur) { return; }
      var e = at(c.t, c.t.length, cur);
      shown[id] = true;
      drawCap(g, v, c.x[e] / 10, c.y[e] / 10, radius(a, id), c.held[e] >= 0);
    });
    a.caps.forEach(function (c, id) {
      if (!shown[id]) { drawCap(g, v, c[0], c[1], c[2], false); }
    });
    var ks = robots.map(function (r) { return at(r.t, r.n, cur); });
    robots.forEach(function (r, i) { drawTrail(g, v, r, ks[i]); });
    a.robots.forEach(function (p) {
      g.strokeStyle = 'rgba(46,139,87,0.5)';
      g.lineWidth = 1;
      g.setLineDash([3, 3]);
      circle(g, v, p[0], p[1], M.robotRadius);
      g.stroke();
      g.setLineDash([]);
    });
    robots.forEach(function (r, i) { drawRobot(g, v, r, ks[i], true); });
    if (robots.length > 1) {
      g.font = 'bold 11px sans-serif';
      robots.forEach(function (r, i) {
        var x = v.x(r.x[ks[i]] / 10), y = v.y(r.y[ks[i]] / 10), rad = v.len(r.radius);
        if (i === selected) {
          g.strokeStyle = C.selection;
          g.lineWidth = 2.5;
          g.beginPath();
          g.arc(x, y, rad + 4, 0, 2 * Math.PI);
          g.stroke();
        }
        g.fillStyle = C.label;
        g.fillText(String(i), x + rad + 3, y - rad);
      });
    }
  }

  function radius(a, id) {
    return id < a.caps.length ? a.caps[id][2] : M.capRadius;
  }

  // ------------------------------------------------------------------ the sensor panel

  var sensorCanvas = $('sensors');

  function drawSensors() {
    var dpr = window.devicePixelRatio || 1, w = sensorCanvas.clientWidth || 300, h = 410;
    if (sensorCanvas.width !== Math.round(w * dpr) || sensorCanvas.height !== Math.round(h * dpr)) {
      sensorCanvas.width = Math.round(w * dpr);
      sensorCanvas.height = Math.round(h * dpr);
    }
    var g = sensorCanvas.getContext('2d');
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.fillStyle = '#FAFAFA';
    g.fillRect(0, 0, w, h);
    var r = robots[selected], k = at(r.t, r.n, cur), area = 260;
    var cx = w / 2, cy = area / 2 + 12, body = Math.min(w, area) * 0.20;
    g.fillStyle = C.robot;
    g.beginPath();
    g.arc(cx, cy, body, 0, 2 * Math.PI);
    g.fill();
    g.strokeStyle = '#FFFFFF';
    g.lineWidth = 3;
    g.lineCap = 'round';
    line(g, cx, cy, cx, cy - body * 0.85);
    g.lineCap = 'butt';
    g.strokeStyle = C.wheel;
    g.lineWidth = 5;
    line(g, cx - body - 1, cy - 8, cx - body - 1, cy + 8);
    line(g, cx + body + 1, cy - 8, cx + body + 1, cy + 8);
    var j = r.sens ? Math.min(r.m - 1, Math.floor(k / RUN.sensorStride)) : -1;
    g.font = '12px sans-serif';
    M.sensors.forEach(function (s, i) {
      var ang = Math.atan2(s[1], s[0]);
      g.fillStyle = C.wheel;
      g.beginPath();
      g.arc(cx - body * Math.sin(ang), cy - body * Math.cos(ang), 3, 0, 2 * Math.PI);
      g.fill();
      var lx = cx - (body + 50) * Math.sin(ang), ly = cy - (body + 50) * Math.cos(ang);
      if (i === 2) { lx -= 34; ly -= 6; } else if (i === 3) { lx += 34; ly -= 6; }
      else if (i === 6) { lx += 36; ly = cy + body + 32; } else if (i === 7) { lx -= 36; ly = cy + body + 32; }
      var prox = j < 0 ? 0 : r.sens[i][j], light = j < 0 ? 0 : r.sens[8 + i][j], bw = 54, x0 = lx - bw / 2;
      g.fillStyle = '#E6E6E6';
      g.fillRect(x0, ly - 9, bw, 6);
      g.fillRect(x0, ly + 9, bw, 6);
      g.fillStyle = C.prox;
      g.fillRect(x0, ly - 9, bw * clamp(prox), 6);
      g.fillStyle = C.light;
      g.fillRect(x0, ly + 9, bw * clamp(light), 6);
      g.fillStyle = '#000000';
      var text = j < 0 ? i + ': - / -' : i + ': ' + prox + ' / ' + light;
      g.fillText(text, lx - g.measureText(text).width / 2, ly + 6);
    });
    var y = area + 10, icon = 46, gap = (w - 3 * icon) / 4;
    var lowered = Math.max(0, Math.min(1, (r.arm[k] - M.armUp) / (M.armDown - M.armUp)));
    var open = r.fingers[k] === M.fingersOpen, present = r.obj[k] === 1;
    armIcon(g, gap, y, icon, lowered);
    fingersIcon(g, 2 * gap + icon, y, icon, open);
    objectIcon(g, 3 * gap + 2 * icon, y, icon, present);
    g.fillStyle = '#333333';
    g.font = '12px sans-serif';
    var armText = r.arm[k] <= M.armUp + 5 ? 'up' : r.arm[k] >= M.armDown - 5 ? 'down' : String(r.arm[k]);
    caption(g, gap + icon / 2, y + icon + 16, 'arm ' + armText);
    caption(g, 2 * gap + 1.5 * icon, y + icon + 16, 'fingers ' + M.fingers[r.fingers[k]]);
    caption(g, 3 * gap + 2.5 * icon, y + icon + 16, present ? 'object: yes' : 'object: no');
    y += icon + 16 + 22;
    g.font = '12.5px ui-monospace, Menlo, Consolas, monospace';
    g.fillStyle = '#000000';
    g.fillText('speed   L ' + pad(r.sl[k], 4) + '   R ' + pad(r.sr[k], 4) + '  (x 8 mm/s)', 8, y);
    g.fillText('encoder L ' + pad(r.el[k], 7) + ' R ' + pad(r.er[k], 7) + '  pulses', 8, y + 16);
    g.fillText('pose (' + (r.x[k] / 10).toFixed(1) + ', ' + (r.y[k] / 10).toFixed(1) + ') mm  '
        + norm(r.h[k]).toFixed(1) + ' deg', 8, y + 32);
    var failed = RUN.failures.filter(function (f) { return f.robot === selected && f.t !== null && f.t <= cur; })[0];
    g.fillStyle = failed ? C.failure : '#000000';
    g.fillText('contact ' + M.contacts[r.contact[k]] + (failed ? '  controller ' + words(failed.status) : ''), 8, y + 48);
    $('readings').textContent = 'robot ' + selected + ' at ' + (cur / 1000).toFixed(3) + ' s: proximity '
        + (j < 0 ? '-' : r.sens.slice(0, 8).map(function (c) { return c[j]; }).join(' ')) + '; light '
        + (j < 0 ? '-' : r.sens.slice(8).map(function (c) { return c[j]; }).join(' ')) + '; speed ' + r.sl[k] + ' ' + r.sr[k]
        + '; encoders ' + r.el[k] + ' ' + r.er[k] + '; pose ' + (r.x[k] / 10).toFixed(1) + ' ' + (r.y[k] / 10).toFixed(1) + ' '
        + norm(r.h[k]).toFixed(1) + '; contact ' + M.contacts[r.contact[k]] + '; arm ' + r.arm[k] + '; fingers '
        + M.fingers[r.fingers[k]] + '; object ' + (present ? 'yes' : 'no');
    $('sensorNote').textContent = !r.sens ? 'The sensor values of robots after the first 16 are not kept.'
        : RUN.sensorStride * RUN.poseStride > 1 ? 'Sensor values every ' + RUN.sampleMs * RUN.poseStride * RUN.sensorStride
        + ' ms (the run sampled every ' + RUN.sampleMs + ' ms; thinned to keep this page small).'
        : 'Sampled every ' + RUN.sampleMs + ' ms.';
  }

  function pad(n, width) { var s = String(n); while (s.length < width) { s = ' ' + s; } return s; }

  function clamp(value) { return Math.max(0, Math.min(1023, value)) / 1023; }

  function caption(g, cx, y, text) { g.fillText(text, cx - g.measureText(text).width / 2, y); }

  function frame(g, x, y, s) {
    g.beginPath();
    if (g.roundRect) { g.roundRect(x, y, s, s, 4); } else { g.rect(x, y, s, s); }
    g.fillStyle = '#FFFFFF';
    g.fill();
    g.strokeStyle = '#B0B0B0';
    g.lineWidth = 1;
    g.stroke();
  }

  function armIcon(g, x, y, s, lowered) {
    frame(g, x, y, s);
    var px = x + s * 0.25, py = y + s * 0.35, ang = (60 - 100 * lowered) * Math.PI / 180, len = s * 0.6;
    g.fillStyle = '#777777';
    g.fillRect(x + 4, y + s * 0.35, s * 0.25, s * 0.45);
    g.strokeStyle = '#305080';
    g.lineWidth = 4;
    g.lineCap = 'round';
    line(g, px, py, px + len * Math.cos(ang), py - len * Math.sin(ang));
    g.lineCap = 'butt';
    g.strokeStyle = '#999999';
    g.lineWidth = 1;
    line(g, x + 2, y + s * 0.85, x + s - 2, y + s * 0.85);
  }

  function fingersIcon(g, x, y, s, open) {
    frame(g, x, y, s);
    var spread = open ? s * 0.3 : s * 0.08, cx = x + s / 2;
    g.strokeStyle = '#305080';
    g.lineWidth = 5;
    g.lineCap = 'round';
    line(g, cx - spread, y + s * 0.2, cx - spread, y + s * 0.8);
    line(g, cx + spread, y + s * 0.2, cx + spread, y + s * 0.8);
    g.lineWidth = 3;
    line(g, cx - s * 0.35, y + s * 0.2, cx + s * 0.35, y + s * 0.2);
    g.lineCap = 'butt';
  }

  function objectIcon(g, x, y, s, present) {
    frame(g, x, y, s);
    g.beginPath();
    g.arc(x + s / 2, y + s / 2, s * 0.2, 0, 2 * Math.PI);
    g.fillStyle = present ? '#FF3030' : '#DDDDDD';
    g.fill();
    g.strokeStyle = '#404040';
    g.lineWidth = 1.5;
    g.stroke();
  }

  // ------------------------------------------------------------------ score, failures, timeline

  function showScore() {
    if (!RUN.scores.length) { return; }
    var s = RUN.scores[0];
    RUN.scores.forEach(function (m) { if (m.t <= cur) { s = m; } });
    var rows = s.parts.map(function (p) {
      var detail = p[1] === '' ? (RUN.coverageAtEnd ? 'floor coverage is counted at the end of the run'
          : 'floor coverage is not recorded in a trace') : p[1];
      return '<tr><td>' + esc(p[0]) + '</td><td>' + esc(detail) + '</td><td class="pts">' + esc(p[2]) + ' / ' + esc(p[3]) + '</td></tr>';
    }).join('');
    $('score').innerHTML = '<div class="total">' + esc(s.points) + ' <small>/ ' + esc(s.max) + (s.pending ? ' so far' : '')
        + '</small></div><div class="bar"><div style="width:' + Math.max(0, Math.min(100, s.percent)).toFixed(1)
        + '%"></div></div><table class="parts">' + rows + '</table>';
  }

  function showFailures() {
    var list = $('fails');
    if (!RUN.failures.length) { return; }
    $('failBox').hidden = false;
    RUN.failures.forEach(function (f, i) {
      var li = document.createElement('li');
      li.id = 'fail' + i;
      var name = robots[f.robot] ? robots[f.robot].name : 'robot ' + f.robot;
      li.innerHTML = '<b>' + esc(name) + '</b> ' + esc(words(f.status)) + ' '
          + (f.t === null ? '(time not recorded)' : 'at ' + (f.t / 1000).toFixed(3) + ' s')
          + (f.message ? '<pre>' + esc(f.message) + '</pre>' : '');
      li.onclick = function () { pause(); selectRobot(f.robot); seek(f.t === null ? endMs : f.t); };
      list.appendChild(li);
    });
  }

  function updateFailures() {
    RUN.failures.forEach(function (f, i) {
      var li = $('fail' + i);
      if (li) { li.className = f.t !== null && f.t > cur ? 'later' : ''; }
    });
  }

  var timeline = $('timeline'), marksLayer = null, marksKey = '';

  function drawTimeline() {
    var dpr = window.devicePixelRatio || 1, w = timeline.clientWidth, h = timeline.clientHeight;
    if (!w || !h) { return; }   // hidden (#only=arena)
    if (timeline.width !== Math.round(w * dpr) || timeline.height !== Math.round(h * dpr)) {
      timeline.width = Math.round(w * dpr);
      timeline.height = Math.round(h * dpr);
    }
    var g = timeline.getContext('2d');
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.clearRect(0, 0, w, h);
    var x0 = 8, x1 = w - 8, span = Math.max(1, endMs - startMs);
    var px = function (t) { return x0 + (x1 - x0) * (t - startMs) / span; };
    g.fillStyle = '#E6E8EC';
    g.fillRect(x0, 17, x1 - x0, 10);
    g.fillStyle = '#9DB8E8';
    g.fillRect(x0, 17, px(cur) - x0, 10);
    // The marks do not move: drawn once for this width, then copied each frame (a swarm's run has thousands).
    var key = w + 'x' + h + ' ' + dpr;
    if (key !== marksKey) {
      marksLayer = document.createElement('canvas');
      marksLayer.width = timeline.width;
      marksLayer.height = timeline.height;
      var mg = marksLayer.getContext('2d');
      mg.setTransform(dpr, 0, 0, dpr, 0, 0);
      var done = {};
      marks.forEach(function (m) {
        var x = Math.round(px(m.t)) + 0.5;
        if (done[m.kind + x] && m.kind !== 'failure') { return; }
        done[m.kind + x] = true;
        if (m.kind === 'contact') {
          mg.strokeStyle = C.contactMark;
          mg.lineWidth = 1;
          line(mg, x, 30, x, 40);
        } else if (m.kind === 'cap') {
          mg.strokeStyle = C.cap;
          mg.lineWidth = 1.5;
          line(mg, x, 4, x, 14);
        } else {
          mg.strokeStyle = C.failure;
          mg.lineWidth = 2.5;
          if (m.failure.t === null) { mg.setLineDash([3, 2]); }
          line(mg, x, 2, x, 44);
          mg.setLineDash([]);
        }
      });
      marksKey = key;
    }
    g.setTransform(1, 0, 0, 1, 0, 0);
    g.drawImage(marksLayer, 0, 0);
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    var cx = px(cur);
    g.fillStyle = '#1d2330';
    g.fillRect(cx - 1, 12, 2, 20);
    g.beginPath();
    g.arc(cx, 22, 5, 0, 2 * Math.PI);
    g.fill();
    g.font = '10px sans-serif';
    g.fillStyle = '#5b6472';
    g.fillText(fmt(startMs) + ' s', x0, 46);
    var endText = fmt(endMs) + ' s';
    g.fillText(endText, x1 - g.measureText(endText).width, 46);
  }

  function timeAtPixel(clientX) {
    var r = timeline.getBoundingClientRect(), x0 = 8, x1 = r.width - 8;
    var f = Math.max(0, Math.min(1, (clientX - r.left - x0) / (x1 - x0)));
    return startMs + f * (endMs - startMs);
  }

  // ------------------------------------------------------------------ playing

  function render() {
    drawArena();
    drawSensors();
    showScore();
    updateFailures();
    drawTimeline();
    $('time').textContent = (cur / 1000).toFixed(2) + ' / ' + (endMs / 1000).toFixed(2) + ' s';
    $('play').textContent = playing ? 'Pause' : 'Play';
    document.body.setAttribute('data-t', (cur / 1000).toFixed(3));
    document.body.setAttribute('data-state', playing ? 'playing' : 'paused');
  }

  function seek(t) {
    cur = Math.max(startMs, Math.min(endMs, t));
    render();
  }

  // A timer, not an animation frame: timers run in every browser and in a headless one's virtual
  // time alike, and a frame every 16 ms is as smooth.
  function schedule(f) {
    setTimeout(function () { f(window.performance ? performance.now() : Date.now()); }, 16);
  }

  function tick(now) {
    if (!playing) { return; }
    var dt = lastFrame ? Math.min(250, now - lastFrame) : 0;
    lastFrame = now;
    cur = Math.min(endMs, cur + dt * speed);
    if (cur >= endMs) { playing = false; }
    render();
    if (playing) { schedule(tick); }
  }

  function play() {
    if (cur >= endMs) { cur = startMs; }
    playing = true;
    lastFrame = 0;
    schedule(tick);
    render();
  }

  function pause() {
    playing = false;
    render();
  }

  function step(dir, ms) {
    pause();
    if (ms) { seek(cur + dir * ms); return; }
    var r = robots[selected], k = at(r.t, r.n, cur);
    var target = dir > 0 ? (r.t[k] <= cur ? k + 1 : k) : (r.t[k] < cur ? k : k - 1);
    seek(r.t[Math.max(0, Math.min(r.n - 1, target))]);
  }

  function jumpMark(dir) {
    pause();
    var next = null;
    marks.forEach(function (m) {
      if (dir > 0 && m.t > cur + 0.5 && next === null) { next = m; }
      if (dir < 0 && m.t < cur - 0.5) { next = m; }
    });
    if (next) { seek(next.t); }
  }

  function setSpeed(s) {
    speed = s;
    var i = SPEEDS.indexOf(s);
    if (i >= 0) { $('speed').selectedIndex = i; }
  }

  function selectRobot(i) {
    if (i >= 0 && i < robots.length) {
      selected = i;
      $('robot').selectedIndex = i;
      render();
    }
  }

  function fromHash() {
    var h = {};
    location.hash.replace(/^#/, '').split('&').forEach(function (p) {
      var kv = p.split('=');
      if (kv[0]) { h[decodeURIComponent(kv[0])] = decodeURIComponent(kv[1] || ''); }
    });
    document.body.classList.toggle('only-arena', h.only === 'arena');
    if (h.robot !== undefined) { selectRobot(parseInt(h.robot, 10)); }
    if (h.speed !== undefined && SPEEDS.indexOf(+h.speed) >= 0) { setSpeed(+h.speed); }
    if (h.t !== undefined && isFinite(+h.t)) { cur = Math.max(startMs, Math.min(endMs, +h.t * 1000)); }
    if (h.play !== undefined) {
      if (SPEEDS.indexOf(+h.play) >= 0) { setSpeed(+h.play); }
      play();
    } else {
      pause();
    }
  }

  function esc(s) {
    return String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
  }

  function about() {
    var p = [];
    if (RUN.source) { p.push('Made from ' + esc(RUN.source) + '.'); }
    p.push(robots.length + (robots.length === 1 ? ' robot' : ' robots') + ', ' + (endMs / 1000).toFixed(1)
        + ' simulated seconds, a sample every ' + RUN.sampleMs * RUN.poseStride + ' ms'
        + (RUN.poseStride > 1 ? ' (every ' + RUN.poseStride + ' samples of the run, to keep this page small)' : '') + '.');
    if (RUN.robotsInRun > robots.length) { p.push('The run had ' + RUN.robotsInRun + ' robots; this page shows the first ' + robots.length + '.'); }
    RUN.notes.forEach(function (n) { p.push(esc(n)); });
    p.push('The score is worked out at every sample by the simulator\'s own scoring; regions count from the first sample a robot\'s centre lies inside'
        + (RUN.coverageAtEnd ? ' (the run\'s own entry times)' : '') + '.');
    p.push('Keys: Space play/pause, Left/Right one sample (Shift: 1 s), [ and ] marks, + and - speed, Home/End. A link ending in #t=12.5 opens this page at 12.5 s.');
    p.push('Everything is inside this one file: it needs no network and no server.');
    $('about').innerHTML = p.map(function (s) { return '<p>' + s + '</p>'; }).join('');
  }

  function start() {
    D = unpack();
    robots = D.robots;
    caps = D.caps;
    if (!robots.length || !robots[0].n) { throw new Error('the run has no sample'); }
    startMs = robots[0].t[0];
    endMs = RUN.endMs;
    cur = startMs;
    // A controller that failed ended its run within the last sample: show it failed there.
    RUN.failures.forEach(function (f) { if (f.t !== null && f.t > endMs) { f.t = endMs; } });
    buildMarks();
    var arena0 = RUN.arenas[0];
    $('sub').textContent = 'arena ' + arena0.name + ' · ' + (endMs / 1000).toFixed(1) + ' s · '
        + (robots.length === 1 ? '1 robot' : robots.length + ' robots');
    SPEEDS.forEach(function (s) {
      var o = document.createElement('option');
      o.textContent = s === 64 ? 'x64 (fastest)' : 'x' + s;
      $('speed').appendChild(o);
    });
    setSpeed(1);
    $('speed').onchange = function () { setSpeed(SPEEDS[$('speed').selectedIndex]); };
    if (robots.length > 1) {
      $('robotPick').hidden = false;
      robots.forEach(function (r, i) {
        var o = document.createElement('option');
        o.textContent = i + ': ' + r.name;
        $('robot').appendChild(o);
      });
      $('robot').onchange = function () { selectRobot($('robot').selectedIndex); };
    }
    if (RUN.scores.length) { $('scoreBox').hidden = false; }
    showFailures();
    about();
    $('play').onclick = function () { if (playing) { pause(); } else { play(); } };
    $('back').onclick = function (e) { step(-1, e.shiftKey ? 1000 : 0); };
    $('fwd').onclick = function (e) { step(1, e.shiftKey ? 1000 : 0); };
    $('prevMark').onclick = function () { jumpMark(-1); };
    $('nextMark').onclick = function () { jumpMark(1); };
    var dragging = false;
    timeline.addEventListener('pointerdown', function (e) {
      dragging = true;
      if (timeline.setPointerCapture) { timeline.setPointerCapture(e.pointerId); }
      pause();
      seek(timeAtPixel(e.clientX));
    });
    timeline.addEventListener('pointermove', function (e) {
      if (dragging) { seek(timeAtPixel(e.clientX)); return; }
      var t = timeAtPixel(e.clientX), tol = 5 * (endMs - startMs) / Math.max(1, timeline.clientWidth - 16), near = null;
      marks.forEach(function (m) { if (Math.abs(m.t - t) <= tol) { near = m; } });
      timeline.title = near ? fmt(near.t) + ' s: ' + near.text : fmt(t) + ' s (click or drag to go there)';
    });
    timeline.addEventListener('pointerup', function () { dragging = false; });
    document.addEventListener('keydown', function (e) {
      if (e.target && (e.target.tagName === 'SELECT' || e.target.tagName === 'INPUT')) { return; }
      var k = e.key;
      if (k === ' ') { if (playing) { pause(); } else { play(); } } else if (k === 'ArrowLeft') { step(-1, e.shiftKey ? 1000 : 0); }
      else if (k === 'ArrowRight') { step(1, e.shiftKey ? 1000 : 0); } else if (k === 'Home') { pause(); seek(startMs); }
      else if (k === 'End') { pause(); seek(endMs); } else if (k === '[') { jumpMark(-1); } else if (k === ']') { jumpMark(1); }
      else if (k === '+' || k === '=') { setSpeed(SPEEDS[Math.min(SPEEDS.length - 1, SPEEDS.indexOf(speed) + 1)]); }
      else if (k === '-') { setSpeed(SPEEDS[Math.max(0, SPEEDS.indexOf(speed) - 1)]); } else { return; }
      e.preventDefault();
    });
    window.addEventListener('resize', function () { render(); });
    window.addEventListener('hashchange', fromHash);
    fromHash();
  }

  try {
    start();
  } catch (e) {
    var box = document.createElement('div');
    box.id = 'problem';
    box.textContent = 'This page cannot replay its run: ' + e.message
        + '. The file may have been cut short or changed; write it again with khepera-sim replay --html.';
    stage.appendChild(box);
    document.body.setAttribute('data-error', e.message);
  }
})();

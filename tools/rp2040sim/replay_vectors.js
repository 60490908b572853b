#!/usr/bin/env node
// SPDX-License-Identifier: MIT
'use strict';
/* replay_vectors.js — replays the emulated-panel test vectors
 * (tests/vectors/panel/*.txt, format in docs/hal.md) through emu_panel.js,
 * the port of hal/sim/emu_panel.c that the RP2040 emulator uses. The C
 * emulator replays the same files (tests/unit/test_panel_vectors.c), so a change
 * in one decoder that the other lacks fails one of the two runs.
 *
 * usage: node replay_vectors.js DIR|FILE...
 * Prints "PASS js:<file>" or "FAIL js:<file>: line N: why" per file.
 * Exit status: 0 all pass, 1 a failure, 2 usage. */
const fs = require('fs');
const path = require('path');
const { EmuPanel, MEM_W, MEM_H } = require('./emu_panel.js');

/* CRC-32 (IEEE, as zlib) of the glass as little-endian uint16, row-major. */
const CRC_TABLE = (() => {
  const t = new Uint32Array(256);
  for (let n = 0; n < 256; n++) {
    let c = n;
    for (let k = 0; k < 8; k++) c = (c & 1) ? (0xEDB88320 ^ (c >>> 1)) : (c >>> 1);
    t[n] = c >>> 0;
  }
  return t;
})();

function glassCrc(px) {
  let crc = 0xFFFFFFFF;
  for (let i = 0; i < px.length; i++) {
    crc = CRC_TABLE[(crc ^ px[i]) & 0xff] ^ (crc >>> 8);
    crc = CRC_TABLE[(crc ^ (px[i] >>> 8)) & 0xff] ^ (crc >>> 8);
  }
  return (crc ^ 0xFFFFFFFF) >>> 0;
}

const hex4 = (v) => v.toString(16).toUpperCase().padStart(4, '0');
const hex8 = (v) => v.toString(16).toUpperCase().padStart(8, '0');
const LINES = { dc: 0, reset: 1, cs: 2, bl: 3 };

/* Hex bytes separated by blanks (at most 256); null when malformed. */
function hexBytes(s) {
  const toks = s.split(/[ \t]+/).filter((x) => x !== '');
  if (toks.length > 256) return null;
  const out = [];
  for (const tk of toks) {
    if (!/^(0[xX])?[0-9a-fA-F]+$/.test(tk)) return null;
    const v = parseInt(tk.replace(/^0[xX]/, ''), 16);
    if (v > 0xFF) return null;
    out.push(v);
  }
  return out;
}

class Run {
  constructor() { this.p = null; this.t = 0; this.nsPerByte = 0; }

  send(bytes) {
    this.p.spi(bytes, this.t, this.nsPerByte);
    this.t += bytes.length * this.nsPerByte;
  }

  /* One statement; returns null or the failure text. */
  step(ln) {
    const m = /^(\S+)\s*(.*)$/.exec(ln);
    const word = m[1];
    const rest = m[2];
    if (word === 'module') {
      try { this.p = new EmuPanel(rest); } catch (e) { return 'unknown module'; }
      this.t = 0;
      this.nsPerByte = 0;
      return null;
    }
    if (!this.p) return "first statement must be 'module'";
    const p = this.p;
    switch (word) {
      case 'view': {
        const v = parseInt(rest, 10);
        try { this.p = new EmuPanel(p.mod.name, Number.isNaN(v) ? 0 : v); } catch (e) { return 'bad view'; }
        return null;
      }
      case 'cs_tied_low': p.csTiedLow = 1; return null;
      case 'line': {
        const a = rest.split(/\s+/);
        if (a.length < 2 || !(a[0] in LINES) || !/^-?\d+$/.test(a[1])) return 'bad line statement';
        p.line(LINES[a[0]], Number(a[1]), this.t);
        return null;
      }
      case 'reset':
        p.line(1, 0, this.t);
        this.t += 10000;
        p.line(1, 1, this.t);
        return null;
      case 'cmd': {
        const b = hexBytes(rest);
        if (!b || b.length < 1) return 'bad cmd bytes';
        p.line(0, 0, this.t);
        this.send(b.slice(0, 1));
        p.line(0, 1, this.t);
        this.send(b.slice(1));
        return null;
      }
      case 'data': {
        const b = hexBytes(rest);
        if (!b || b.length < 1) return 'bad data bytes';
        p.line(0, 1, this.t);
        this.send(b);
        return null;
      }
      case 'pixels': {
        const a = rest.split(/\s+/).filter((x) => x !== '');
        const count = /^\d+$/.test(a[0] || '') ? Number(a[0]) : 0;
        const px = [];
        for (const tk of a.slice(1, 65)) {
          if (!/^[0-9a-fA-F]+$/.test(tk)) break;
          px.push(parseInt(tk, 16) & 0xffff);
        }
        if (!px.length || !count) return 'bad pixels statement';
        p.line(0, 1, this.t);
        const b = new Uint8Array(2 * count);
        for (let i = 0; i < count; i++) {
          b[2 * i] = px[i % px.length] >> 8;
          b[2 * i + 1] = px[i % px.length] & 0xff;
        }
        this.send(b);
        return null;
      }
      case 'delay_ms': this.t += (parseInt(rest, 10) || 0) * 1000000; return null;
      case 'delay_us': this.t += (parseInt(rest, 10) || 0) * 1000; return null;
      case 'spi_ns': this.nsPerByte = parseInt(rest, 10) || 0; return null;
      case 'finish': p.finish(this.t); return null;
      case 'expect_ok':
        return p.violation ? `unexpected violation: ${p.violation}` : null;
      case 'expect_violation':
        return p.violation === rest ? null : `violation "${p.violation || '(none)'}", want "${rest}"`;
      case 'expect_size': {
        const a = rest.split(/\s+/).map(Number);
        if (a.length < 2 || a.some(Number.isNaN)) return 'bad expect_size';
        if (a[0] !== p.glassWidth() || a[1] !== p.glassHeight()) {
          return `glass ${p.glassWidth()}x${p.glassHeight()}, want ${a[0]}x${a[1]}`;
        }
        return null;
      }
      case 'expect_glass':
      case 'expect_mem': {
        const a = rest.split(/\s+/);
        if (a.length < 3 || !/^\d+$/.test(a[0]) || !/^\d+$/.test(a[1]) || !/^[0-9a-fA-F]+$/.test(a[2])) {
          return 'bad expect statement';
        }
        const x = Number(a[0]), y = Number(a[1]), want = parseInt(a[2], 16);
        let got;
        if (word === 'expect_glass') {
          const w = p.glassWidth(), h = p.glassHeight();
          if (x >= w || y >= h) return 'pixel outside the glass';
          got = p.glass()[y * w + x];
        } else {
          got = x < MEM_W && y < MEM_H ? p.memAt(x, y) : 0;
        }
        return got === want ? null : `${word} ${x} ${y} is ${hex4(got)}, want ${hex4(want)}`;
      }
      case 'expect_glass_crc32': {
        const want = parseInt(rest, 16) >>> 0, got = glassCrc(p.glass());
        return got === want ? null : `glass crc32 ${hex8(got)}, want ${hex8(want)}`;
      }
      default:
        return `unknown statement '${word}'`;
    }
  }
}

function runFile(file) {
  let text;
  try { text = fs.readFileSync(file, 'utf8'); } catch (e) { return 'cannot open'; }
  const run = new Run();
  let expects = 0, lineno = 0;
  for (const raw of text.split('\n')) {
    lineno++;
    const s = raw.replace(/#.*$/, '').trim();
    if (!s) continue;
    if (s.startsWith('expect')) expects++;
    const why = run.step(s);
    if (why) return `line ${lineno}: ${why}`;
  }
  return expects ? null : `line ${lineno}: no expectations`;
}

function main() {
  const args = process.argv.slice(2);
  if (!args.length) {
    process.stderr.write('usage: replay_vectors.js DIR|FILE...\n');
    process.exit(2);
  }
  let files = 0, failed = 0;
  for (const a of args) {
    let list = [a];
    let st = null;
    try { st = fs.statSync(a); } catch (e) { /* reported as cannot open */ }
    if (st && st.isDirectory()) {
      list = fs.readdirSync(a).filter((n) => n.length > 4 && n.endsWith('.txt')).sort()
        .map((n) => path.join(a, n));
    }
    for (const f of list) {
      files++;
      const why = runFile(f);
      if (why) { failed++; process.stdout.write(`FAIL js:${f}: ${why}\n`); } else process.stdout.write(`PASS js:${f}\n`);
    }
  }
  if (!files) { failed++; process.stdout.write('FAIL js:vectors_found: no vector files given\n'); }
  process.exit(failed ? 1 : 0);
}

main();

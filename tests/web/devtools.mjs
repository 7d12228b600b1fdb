// What the browser tests share: build-web/web/ served from 127.0.0.1, and headless chromium
// driven over the DevTools protocol's pipe transport (NUL-terminated JSON on file descriptors 3
// and 4), one page attached, with the calls the tests make of it.
import { spawn, spawnSync } from 'node:child_process';
import { createServer } from 'node:http';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { extname, join } from 'node:path';
import { inflateSync } from 'node:zlib';

// A PNG's pixels as RGBA bytes (8-bit RGB or RGBA, no interlace: what savePng writes).
export function decodePng(bytes) {
  let at = 8, width = 0, height = 0, type = 0;
  const idat = [];
  while (at < bytes.length) {
    const length = bytes.readUInt32BE(at), name = bytes.toString('latin1', at + 4, at + 8);
    const data = bytes.subarray(at + 8, at + 8 + length);
    if (name === 'IHDR') {
      width = data.readUInt32BE(0); height = data.readUInt32BE(4); type = data[9];
      if (data[8] !== 8 || (type !== 2 && type !== 6) || data[12] !== 0) fail('unexpected PNG format');
    } else if (name === 'IDAT') idat.push(data);
    at += 12 + length;
  }
  const channels = type === 6 ? 4 : 3, stride = width * channels;
  const raw = inflateSync(Buffer.concat(idat)), out = Buffer.alloc(width * height * 4);
  let previous = Buffer.alloc(stride);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)], row = Buffer.from(raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1)));
    for (let i = 0; i < stride; ++i) {
      const a = i >= channels ? row[i - channels] : 0, b = previous[i], c = i >= channels ? previous[i - channels] : 0;
      let p = 0;
      if (filter === 1) p = a;
      else if (filter === 2) p = b;
      else if (filter === 3) p = (a + b) >> 1;
      else if (filter === 4) {
        const e = a + b - c, da = Math.abs(e - a), db = Math.abs(e - b), dc = Math.abs(e - c);
        p = da <= db && da <= dc ? a : db <= dc ? b : c;
      }
      row[i] = (row[i] + p) & 255;
    }
    for (let x = 0; x < width; ++x)
      for (let k = 0; k < 4; ++k) out[(y * width + x) * 4 + k] = k < channels ? row[x * channels + k] : 255;
    previous = row;
  }
  return { width, height, pixels: out };
}

export const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

// Exits 77 (ctest's skip) when there is no chromium.
export function skipWithoutChromium() {
  if (!spawnSync('chromium', ['--version']).error) return;
  console.log('SKIP: chromium is not installed (tools/test and tools/web install it)');
  process.exit(77);
}

export function fail(message) {
  console.error('FAIL: ' + message);
  process.exitCode = 1;
  throw new Error(message);
}

// The page's files from 127.0.0.1 on a free port. While `offline` is set the server hangs up on
// every request: the network is gone.
export async function serve(webDir) {
  const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm', '.data': 'application/octet-stream' };
  const site = { offline: false, requests: 0 };
  const server = createServer((request, response) => {
    ++site.requests;
    if (site.offline) { request.socket.destroy(); return; }
    const path = new URL(request.url, 'http://x').pathname;
    try {
      const body = readFileSync(join(webDir, path === '/' ? 'index.html' : path.replace(/\.\./g, '')));
      response.writeHead(200, { 'Content-Type': types[extname(path)] || 'text/html', 'Cache-Control': 'no-store' });
      response.end(body);
    } catch {
      response.writeHead(404);
      response.end();
    }
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  site.base = `http://127.0.0.1:${server.address().port}/`;
  site.close = () => server.close();
  return site;
}

// Headless chromium with one page attached: `send` is a DevTools call on the page (or, with
// `sessionId` null, on the browser), and the rest are the tests' common steps.
export class Chromium {
  static async launch() {
    const chromium = new Chromium();
    const { targetId } = await chromium.send('Target.createTarget', { url: 'about:blank' }, null);
    chromium.targetId = targetId;
    ({ sessionId: chromium.session } = await chromium.send('Target.attachToTarget', { targetId, flatten: true }, null));
    await chromium.send('Runtime.enable');
    await chromium.send('Page.enable');
    return chromium;
  }

  constructor() {
    this.profile = mkdtempSync(join(tmpdir(), 'polarcade-chromium-'));
    this.process = spawn('chromium', ['--headless=new', '--remote-debugging-pipe', '--no-sandbox', '--disable-gpu',
      '--no-first-run', '--no-default-browser-check', '--mute-audio', '--autoplay-policy=no-user-gesture-required',
      `--user-data-dir=${this.profile}`, '--window-size=1400,1000', 'about:blank'],
      { stdio: ['ignore', 'ignore', 'pipe', 'pipe', 'pipe'] });
    this.log = '';
    this.process.stderr.on('data', (d) => { this.log += d; });
    this.nextId = 1;
    this.pending = new Map();
    this.consoleLines = [];
    this.pageErrors = [];
    this.dialogs = [];
    let buffered = '';
    this.process.stdio[4].on('data', (chunk) => {
      buffered += chunk.toString();
      let end;
      while ((end = buffered.indexOf('\0')) >= 0) {
        this.receive(JSON.parse(buffered.slice(0, end)));
        buffered = buffered.slice(end + 1);
      }
    });
  }

  receive(message) {
    if (message.id && this.pending.has(message.id)) {
      const { resolve, reject, timer } = this.pending.get(message.id);
      this.pending.delete(message.id);
      clearTimeout(timer);
      if (message.error) reject(new Error(JSON.stringify(message.error)));
      else resolve(message.result);
    } else if (message.method === 'Runtime.consoleAPICalled') {
      this.consoleLines.push(message.params.args.map((a) => a.value ?? a.description).join(' '));
    } else if (message.method === 'Page.javascriptDialogOpening') {
      this.dialogs.push(message.params.type);  // a page that asks before it is left: leave
      this.send('Page.handleJavaScriptDialog', { accept: true }, message.sessionId).catch(() => {});
    } else if (message.method === 'Runtime.exceptionThrown') {
      const details = message.params.exceptionDetails;
      this.consoleLines.push('exception: ' + (details.exception?.description ?? details.text));
      this.pageErrors.push(this.consoleLines[this.consoleLines.length - 1]);
    }
  }

  send(method, params = {}, sessionId = this.session) {
    const id = this.nextId++;
    this.process.stdio[3].write(JSON.stringify({ id, method, params, sessionId: sessionId ?? undefined }) + '\0');
    return new Promise((resolve, reject) => {
      const timer = setTimeout(() => reject(new Error(`${method}: no answer in 60 s`)), 60000);
      this.pending.set(id, { resolve, reject, timer });
    });
  }

  async evaluate(expression) {
    const result = await this.send('Runtime.evaluate', { expression, awaitPromise: true, returnByValue: true });
    if (result.exceptionDetails) fail(`${expression}: ${result.exceptionDetails.exception?.description}`);
    return result.result.value;
  }

  // Opens `url` (or reloads, without one) and waits for the game's first frame; returns its time
  // after the navigation started, in ms.
  async open(url) {
    if (url) await this.send('Page.navigate', { url });
    else await this.send('Page.reload', { ignoreCache: true });
    const loaded = Date.now();
    while (!(await this.evaluate("typeof Module === 'object' && Module.firstFrameMs !== undefined && Module._polar_web_probe !== undefined"))) {
      if (Date.now() - loaded > 30000) fail(`${url ?? 'a reload'}: no frame within 30 s\n${this.consoleLines.join('\n')}`);
      await sleep(100);
    }
    return this.evaluate('Module.firstFrameMs');
  }

  // The last frame's numbers (game/web/main.cpp's polar_web_probe).
  async probe() {
    return JSON.parse(await this.evaluate('UTF8ToString(Module._polar_web_probe())'));
  }

  async waitFor(what, test, seconds) {
    const start = Date.now();
    for (;;) {
      const state = await this.probe();
      if (test(state)) return state;
      if (Date.now() - start > seconds * 1000) fail(`${what} within ${seconds} s; the page shows ${JSON.stringify(state)}`);
      await sleep(50);
    }
  }

  async key(type, code) {
    const keys = { Space: [' ', 32], ArrowUp: ['ArrowUp', 38], ArrowLeft: ['ArrowLeft', 37], ArrowDown: ['ArrowDown', 40],
      Enter: ['Enter', 13], Escape: ['Escape', 27], End: ['End', 35], KeyH: ['h', 72], KeyE: ['e', 69] };
    const [keyName, vk] = keys[code];
    await this.send('Input.dispatchKeyEvent', { type, code, key: keyName, windowsVirtualKeyCode: vk, text: type === 'keyDown' && keyName.length === 1 ? keyName : undefined });
  }

  async press(code) {
    await this.key('keyDown', code);
    await sleep(60);
    await this.key('keyUp', code);
    await sleep(60);
  }

  // Fingers on the page (touch emulation on): `points` are all the fingers down after the change.
  touch(type, points) {
    return this.send('Input.dispatchTouchEvent', { type, touchPoints: points });
  }

  async tap(x, y) {
    await this.touch('touchStart', [{ x, y, id: 9 }]);
    await sleep(60);
    await this.touch('touchEnd', []);
    await sleep(60);
  }

  // The canvas's pixels, RGBA, against the PNG at `pngPath` byte for byte (fails naming the first
  // pixel that differs); returns the decoded PNG.
  async expectCanvas(pngPath) {
    const golden = decodePng(readFileSync(pngPath));
    const canvas = Buffer.from((await this.evaluate(`(() => {
      const c = Module.canvas, d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let s = ''; for (let i = 0; i < d.length; i += 8192) s += String.fromCharCode.apply(null, d.subarray(i, i + 8192));
      return btoa(s); })()`)), 'base64');
    if (canvas.length !== golden.pixels.length) fail(`the canvas holds ${canvas.length / 4} pixels, ${pngPath} ${golden.width}x${golden.height}`);
    let differing = 0, first = -1;
    for (let i = 0; i < canvas.length; i += 4)
      if (canvas.compare(golden.pixels, i, i + 4, i, i + 4) !== 0) { if (first < 0) first = i / 4; ++differing; }
    if (differing) fail(`${differing} canvas pixels differ from ${pngPath}, the first at (${first % golden.width}, ${Math.floor(first / golden.width)})`);
    return golden;
  }

  // An element's rectangle in CSS pixels, with its centre.
  rectOf(selector) {
    return this.evaluate(`(() => { const r = document.querySelector(${JSON.stringify(selector)}).getBoundingClientRect();
      return { x: r.x, y: r.y, w: r.width, h: r.height, cx: r.x + r.width / 2, cy: r.y + r.height / 2 }; })()`);
  }

  async close() {
    for (const { timer } of this.pending.values()) clearTimeout(timer);
    this.process.kill();
    await sleep(200);
    rmSync(this.profile, { recursive: true, force: true });
  }
}

// The web page in a real browser: headless chromium, driven over the DevTools protocol (its pipe
// transport: NUL-terminated JSON on file descriptors 3 and 4), against build-web/web/ served from
// 127.0.0.1. Usage: node page_test.mjs WEB_DIR REPLAY PNG TICK [SCREENSHOT.png]
// Checks, in order: the replay's frame after TICK drawn in the page equals PNG byte for byte; key
// presses start a game, thrust moves the ship and fire makes a bullet (with sound); a high score
// entered with the keys is still there after a reload; a corrupt stored table gives an empty one
// and a console message; a gamepad starts a game and moves the ship; on a phone's metrics a tap
// starts a game, three fingers turn, thrust and fire at once and hit a rock, and a swipe and a long
// press neither scroll, zoom nor select; the web render benchmark (bench/ beside the page) prints
// its frame times and finds its kernels' bytes equal. Exits 1 with the reason when a check fails,
// 77 when there is no chromium.
import { spawn, spawnSync } from 'node:child_process';
import { createServer } from 'node:http';
import { mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, extname, join } from 'node:path';
import { gzipSync, inflateSync } from 'node:zlib';

if (spawnSync('chromium', ['--version']).error) {
  console.log('SKIP: chromium is not installed (tools/test and tools/web install it)');
  process.exit(77);
}

const [webDir, replayPath, pngPath, tickText, screenshotPath] = process.argv.slice(2);
const tick = Number(tickText);

function fail(message) {
  console.error('FAIL: ' + message);
  process.exitCode = 1;
  throw new Error(message);
}

// A PNG's pixels as RGBA bytes (8-bit RGB or RGBA, no interlace: what savePng writes).
function decodePng(bytes) {
  let at = 8, width = 0, height = 0, type = 0;
  const idat = [];
  while (at < bytes.length) {
    const length = bytes.readUInt32BE(at), name = bytes.toString('latin1', at + 4, at + 8);
    const data = bytes.subarray(at + 8, at + 8 + length);
    if (name === 'IHDR') {
      width = data.readUInt32BE(0); height = data.readUInt32BE(4); type = data[9];
      if (data[8] !== 8 || (type !== 2 && type !== 6) || data[12] !== 0) fail('unexpected PNG format in ' + pngPath);
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

// The page's files, from 127.0.0.1 on a free port.
// With `offline` set the server hangs up on every request: the network is gone.
const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm', '.data': 'application/octet-stream' };
let offline = false, requests = 0;
const server = createServer((request, response) => {
  ++requests;
  if (offline) { request.socket.destroy(); return; }
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
const base = `http://127.0.0.1:${server.address().port}/`;

const profile = mkdtempSync(join(tmpdir(), 'polarcade-chromium-'));
const browser = spawn('chromium', ['--headless=new', '--remote-debugging-pipe', '--no-sandbox', '--disable-gpu',
  '--no-first-run', '--no-default-browser-check', '--mute-audio', '--autoplay-policy=no-user-gesture-required',
  `--user-data-dir=${profile}`, '--window-size=1400,1000', 'about:blank'],
  { stdio: ['ignore', 'ignore', 'pipe', 'pipe', 'pipe'] });
let browserLog = '';
browser.stderr.on('data', (d) => { browserLog += d; });

// The DevTools protocol over the pipe: each message is JSON ended by a NUL byte.
let nextId = 1, pending = new Map(), buffered = '', consoleLines = [], pageErrors = [], dialogs = [];
browser.stdio[4].on('data', (chunk) => {
  buffered += chunk.toString();
  let end;
  while ((end = buffered.indexOf('\0')) >= 0) {
    const message = JSON.parse(buffered.slice(0, end));
    buffered = buffered.slice(end + 1);
    if (message.id && pending.has(message.id)) {
      const { resolve, reject, timer } = pending.get(message.id);
      pending.delete(message.id);
      clearTimeout(timer);
      if (message.error) reject(new Error(JSON.stringify(message.error)));
      else resolve(message.result);
    } else if (message.method === 'Runtime.consoleAPICalled') {
      consoleLines.push(message.params.args.map((a) => a.value ?? a.description).join(' '));
    } else if (message.method === 'Page.javascriptDialogOpening') {
      dialogs.push(message.params.type);  // a page that asks before it is left: leave
      send('Page.handleJavaScriptDialog', { accept: true }, message.sessionId).catch(() => {});
    } else if (message.method === 'Runtime.exceptionThrown') {
      consoleLines.push('exception: ' + (message.params.exceptionDetails.exception?.description ?? message.params.exceptionDetails.text));
      pageErrors.push(consoleLines[consoleLines.length - 1]);
    }
  }
});
function send(method, params = {}, sessionId) {
  const id = nextId++;
  browser.stdio[3].write(JSON.stringify({ id, method, params, sessionId }) + '\0');
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`${method}: no answer in 60 s`)), 60000);
    pending.set(id, { resolve, reject, timer });
  });
}
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

let session;
async function evaluate(expression) {
  const result = await send('Runtime.evaluate', { expression, awaitPromise: true, returnByValue: true }, session);
  if (result.exceptionDetails) fail(`${expression}: ${result.exceptionDetails.exception?.description}`);
  return result.result.value;
}
async function open(url) {
  await send('Page.navigate', { url }, session);
  const loaded = Date.now();
  while (!(await evaluate("typeof Module === 'object' && Module.firstFrameMs !== undefined && Module._polar_web_probe !== undefined"))) {
    if (Date.now() - loaded > 30000) fail(`${url}: no frame within 30 s\n${consoleLines.join('\n')}`);
    await sleep(100);
  }
  return evaluate('Module.firstFrameMs');
}
const probe = async () => JSON.parse(await evaluate('UTF8ToString(Module._polar_web_probe())'));
async function waitFor(what, test, seconds) {
  const start = Date.now();
  for (;;) {
    const state = await probe();
    if (test(state)) return state;
    if (Date.now() - start > seconds * 1000) fail(`${what} within ${seconds} s; the page shows ${JSON.stringify(state)}`);
    await sleep(50);
  }
}
const keys = { Space: [' ', 32], ArrowUp: ['ArrowUp', 38], ArrowLeft: ['ArrowLeft', 37] };
async function key(type, code) {
  const [keyName, vk] = keys[code];
  await send('Input.dispatchKeyEvent', { type, code, key: keyName, windowsVirtualKeyCode: vk, text: type === 'keyDown' && keyName.length === 1 ? keyName : undefined }, session);
}
async function press(code) {
  await key('keyDown', code);
  await sleep(60);
  await key('keyUp', code);
  await sleep(60);
}

try {
  const { targetId } = await send('Target.createTarget', { url: 'about:blank' });
  ({ sessionId: session } = await send('Target.attachToTarget', { targetId, flatten: true }));
  await send('Runtime.enable', {}, session);
  await send('Page.enable', {}, session);

  // 1. The replay's frame after `tick`, drawn in the page, against the native renderer's PNG.
  const firstFrame = await open(base + '?mute');
  console.log(`first frame ${firstFrame.toFixed(0)} ms after the navigation started`);
  const replayText = readFileSync(replayPath, 'latin1');
  await evaluate(`FS.writeFile('/tmp/golden.replay', ${JSON.stringify(replayText)}); 0`);
  const shown = await evaluate(`Module.ccall('polar_web_show_replay', 'number', ['string', 'number'], ['/tmp/golden.replay', ${tick}])`);
  if (shown !== 0) fail(`the page could not play ${replayPath}:\n${consoleLines.join('\n')}`);
  const golden = decodePng(readFileSync(pngPath));
  const canvas = Buffer.from((await evaluate(`(() => {
    const c = Module.canvas, d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let s = ''; for (let i = 0; i < d.length; i += 8192) s += String.fromCharCode.apply(null, d.subarray(i, i + 8192));
    return c.width + 'x' + c.height + ':' + btoa(s); })()`)).replace(/^\d+x\d+:/, ''), 'base64');
  if (canvas.length !== golden.pixels.length) fail(`the canvas holds ${canvas.length / 4} pixels, ${pngPath} ${golden.width}x${golden.height}`);
  let differing = 0, first = -1;
  for (let i = 0; i < canvas.length; i += 4)
    if (canvas.compare(golden.pixels, i, i + 4, i, i + 4) !== 0) { if (first < 0) first = i / 4; ++differing; }
  if (differing) fail(`${differing} canvas pixels differ from ${pngPath}, the first at (${first % golden.width}, ${Math.floor(first / golden.width)})`);
  console.log(`PASS the canvas after tick ${tick} of ${replayPath} equals ${pngPath} (${golden.width}x${golden.height}, every byte)`);

  // 2. Keys: start, thrust moves the ship, fire makes a bullet.
  await open(base + '?lives=1&seed=3');  // with sound: WebAudio runs (chromium's output muted)
  await press('Space');
  const start = await waitFor('a game started by Space', (s) => s.screen === 'playing' && s.ship, 5);
  await key('keyDown', 'ArrowUp');
  const moved = await waitFor('the ship moved by thrust', (s) => s.ship && Math.hypot(s.ship[0] - start.ship[0], s.ship[1] - start.ship[1]) > 5, 5);
  await key('keyUp', 'ArrowUp');
  console.log(`PASS thrust moved the ship from (${start.ship.map((v) => v.toFixed(1))}) to (${moved.ship.map((v) => v.toFixed(1))})`);
  await key('keyDown', 'Space');
  const fired = await waitFor('a bullet after fire', (s) => s.bullets > 0, 3);
  console.log(`PASS fire: ${fired.bullets} bullet(s) in flight`);
  const audio = await evaluate("Module.polarAudio ? Module.polarAudio.filter((d) => d).map((d) => d.context.state).join(',') : 'none'");
  if (!audio.includes('running')) fail(`the game's sound is not playing: WebAudio is ${audio}`);
  console.log(`PASS sound: WebAudio is ${audio}`);
  if (screenshotPath) {
    const { data } = await send('Page.captureScreenshot', { format: 'png' }, session);
    writeFileSync(screenshotPath, Buffer.from(data, 'base64'));
    console.log(`saved a screenshot of the page to ${screenshotPath}`);
  }

  // 3. A high score: fire while turning until something is hit, thrust into the cave until the
  // only life is lost, then enter the name; a reload must show it.
  await key('keyDown', 'ArrowLeft');
  await waitFor('a score from firing', (s) => s.score > 0 || s.screen !== 'playing', 60);
  await key('keyUp', 'ArrowLeft');
  await key('keyUp', 'Space');
  await key('keyDown', 'ArrowUp');
  const over = await waitFor('the game over after thrusting', (s) => s.screen === 'game-over', 60);
  await key('keyUp', 'ArrowUp');
  if (over.score <= 0) fail('the game ended with no score: nothing to enter');
  await sleep(1700);  // game over takes confirm after 1.5 s
  await press('Space');
  await waitFor('the name entry', (s) => s.screen === 'name-entry', 5);
  for (let i = 0; i < 3; ++i) await press('Space');
  await waitFor('the table with the new score', (s) => s.screen === 'title' && s.highScores.some((e) => e.score === over.score), 5);
  await evaluate(`new Promise((resolve) => { Module.onDataSaved = resolve; })`);
  await open(base + '?mute');
  const reloaded = await waitFor('the high score after a reload', (s) => s.highScores.length > 0, 5);
  if (!reloaded.highScores.some((e) => e.name === 'AAA' && e.score === over.score))
    fail(`after a reload the table is ${JSON.stringify(reloaded.highScores)}; expected AAA ${over.score}`);
  console.log(`PASS the high score AAA ${over.score} was kept over a reload`);

  // 4. A corrupt stored table: an empty table and a console message, the game running on.
  await evaluate(`FS.writeFile('/data/polarcade/highscores.json', '{"format": 1, "scores": [{'); 0`);
  await evaluate(`new Promise((resolve) => { Module.onDataSaved = resolve; })`);
  consoleLines = [];
  await open(base + '?mute');
  const fresh = await waitFor('an empty table after a corrupt one', (s) => s.screen === 'title' && s.tick > 10, 5);
  if (fresh.highScores.length !== 0) fail(`a corrupt table was read as ${JSON.stringify(fresh.highScores)}`);
  if (!consoleLines.some((line) => line.includes('highscores.json')))
    fail(`no console message names the corrupt table; the console says:\n${consoleLines.join('\n')}`);
  console.log(`PASS a corrupt table: an empty one, and the console says: ${consoleLines.find((l) => l.includes('highscores.json'))}`);
  // 5. A gamepad (the Gamepad API, stood in for by a pad the test holds): A starts a game, and a
  // stick held up thrusts the ship away from where it started.
  await evaluate(`(() => {
    const buttons = Array.from({ length: 17 }, () => ({ pressed: false, value: 0 }));
    window.testPad = { connected: true, index: 0, id: 'test pad', mapping: 'standard', timestamp: 0, axes: [0, 0, 0, 0], buttons };
    navigator.getGamepads = () => [window.testPad];
    return 0; })()`);
  const setPad = (change) => evaluate(`(() => { ${change}; window.testPad.timestamp += 1; return 0; })()`);
  await sleep(200);
  await setPad('window.testPad.buttons[0] = { pressed: true, value: 1 }');
  await sleep(150);
  await setPad('window.testPad.buttons[0] = { pressed: false, value: 0 }');
  const padStart = await waitFor('a game started by the pad\'s A', (s) => s.screen === 'playing' && s.ship, 5);
  await setPad('window.testPad.axes[1] = -1');
  const padMoved = await waitFor('the ship moved by the stick', (s) => s.ship && Math.hypot(s.ship[0] - padStart.ship[0], s.ship[1] - padStart.ship[1]) > 5, 5);
  console.log(`PASS gamepad: A started a game, the stick moved the ship to (${padMoved.ship.map((v) => v.toFixed(1))})`);

  // 6. Touch, with a phone's metrics: a tap starts a game, three fingers turn, thrust and fire at
  // once and hit a rock; a swipe and a long press neither scroll, zoom nor select.
  const touch = (type, points) => send('Input.dispatchTouchEvent', { type, touchPoints: points }, session);
  const tap = async (x, y) => { await touch('touchStart', [{ x, y, id: 9 }]); await sleep(60); await touch('touchEnd', []); await sleep(60); };
  const rectOf = (selector) => evaluate(`(() => { const r = document.querySelector(${JSON.stringify(selector)}).getBoundingClientRect();
    return { x: r.x, y: r.y, w: r.width, h: r.height, cx: r.x + r.width / 2, cy: r.y + r.height / 2 }; })()`);
  await send('Emulation.setDeviceMetricsOverride', { width: 412, height: 915, deviceScaleFactor: 2.625, mobile: true }, session);
  await send('Emulation.setTouchEmulationEnabled', { enabled: true, maxTouchPoints: 5 }, session);
  await open(base + '?lives=3&seed=3');
  // The first touch brings the touch controls, which take room from the canvas: tap on the title's
  // first row, PLAY (canvas rows 136-158 of 360, centred: game/app/screens/title_screen.cpp), where
  // it is once they are shown.
  let picture = await rectOf('#canvas');
  await tap(picture.x + picture.w * 320 / 640, picture.y + picture.h * 147 / 360);
  await sleep(300);
  picture = await rectOf('#canvas');
  await tap(picture.x + picture.w * 320 / 640, picture.y + picture.h * 147 / 360);
  const touchStart = await waitFor('a game started by a tap on the game', (s) => s.screen === 'playing' && s.ship, 5);
  if ((await evaluate('document.body.dataset.device')) !== 'touch') fail('the first touch did not show the touch controls');
  const [left, thrust, fire] = await Promise.all(['[data-key=ArrowLeft]', '[data-key=ArrowUp]', '[data-key=Space]'].map(rectOf));
  await touch('touchStart', [{ x: left.cx, y: left.cy, id: 1 }, { x: thrust.cx, y: thrust.cy, id: 2 }, { x: fire.cx, y: fire.cy, id: 3 }]);
  const together = await waitFor('the ship moved, turned and fired under three fingers', (s) => s.ship && s.bullets > 0 &&
    Math.hypot(s.ship[0] - touchStart.ship[0], s.ship[1] - touchStart.ship[1]) > 5 && Math.abs(s.heading - touchStart.heading) > 0.3, 5);
  const held = await evaluate("document.querySelectorAll('.touch-controls .held').length");
  if (held !== 3) fail(`three fingers hold ${held} controls`);
  console.log(`PASS three fingers at once: the ship moved from (${touchStart.ship.map((v) => v.toFixed(1))}) to (${together.ship.map((v) => v.toFixed(1))}), turned ${(together.heading - touchStart.heading).toFixed(2)} rad, ${together.bullets} bullet(s)`);
  await touch('touchMove', [{ x: left.cx, y: left.cy, id: 1 }, { x: fire.cx, y: fire.cy, id: 3 }]);  // thrust lifted
  const hit = await waitFor('a rock hit by turning and firing', (s) => s.score > 0, 60);
  await touch('touchEnd', []);
  console.log(`PASS a rock hit by touch: score ${hit.score}`);
  // A swipe across the game and a long press on the legend: the page stays put, nothing selected.
  await touch('touchStart', [{ x: picture.x + 20, y: picture.cy, id: 4 }]);
  for (let i = 1; i <= 6; ++i) { await touch('touchMove', [{ x: picture.x + 20 + i * 40, y: picture.cy + i * 30, id: 4 }]); await sleep(16); }
  await touch('touchEnd', []);
  const legend = await rectOf('.legend.touch');
  await touch('touchStart', [{ x: legend.cx, y: legend.cy, id: 5 }]);
  await sleep(900);
  await touch('touchEnd', []);
  const still = await evaluate('[window.scrollX, window.scrollY, window.visualViewport.scale, String(getSelection())].join(" ")');
  if (still !== '0 0 1 ') fail(`a swipe and a long press moved the page: scroll, zoom and selection are ${still}`);
  console.log('PASS a swipe and a long press: no scroll, no zoom, nothing selected');

  // 7. The web render benchmark (build-web/web/bench/): the render benchmark's 500-sprite scene,
  // scalar against SIMD128, timed in this browser; its kernels must draw the same bytes.
  consoleLines = [];
  await send('Page.navigate', { url: base + 'bench/polarcade-render-bench.html' }, session);
  const benchStart = Date.now();
  while (!consoleLines.some((line) => line.startsWith('web render bench done') || line.startsWith('FAIL'))) {
    if (Date.now() - benchStart > 120000) fail(`the web render benchmark did not finish in 120 s:\n${consoleLines.join('\n')}`);
    await sleep(100);
  }
  for (const line of consoleLines) console.log('  ' + line);
  if (consoleLines.some((line) => line.startsWith('FAIL'))) fail('the web render benchmark\'s kernels drew different bytes');
  console.log('PASS the web render benchmark ran in chromium and its kernels drew the same bytes');

  if (pageErrors.length) fail(`the page threw:\n${pageErrors.join('\n')}`);
} catch (error) {
  if (!process.exitCode) console.error('FAIL: ' + error.message);
  process.exitCode = 1;
} finally {
  for (const { timer } of pending.values()) clearTimeout(timer);
  browser.kill();
  server.close();
  await sleep(200);
  rmSync(profile, { recursive: true, force: true });
}

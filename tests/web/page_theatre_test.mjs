// The replay theatre in the page, in headless chromium over DevTools: a replay file opened with the
// page's file picker (DOM.setFileInputFiles, as a player's pick) or dropped on it plays in the theatre, and with its
// bar hidden (H) at its last tick (End) the canvas is the native verifier's golden frame, byte for
// byte; seeks made by clicking the seek bar are timed where a player makes them (restore, stepping
// and the frame drawn after, as the page's probe reports them: median and worst printed); a game
// played in the page is kept in IndexedDB across a reload (and a setting changed in Options), the
// list exports it as a download (E), and plays it.
// Usage: node page_theatre_test.mjs WEB_DIR REPLAY PNG LONG_REPLAY, where PNG is REPLAY's frame at
// its last tick and LONG_REPLAY is seeked in. Exits 1 with the reason when a check fails, 77 when
// there is no chromium.
import { mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { Chromium, fail, serve, skipWithoutChromium, sleep } from './devtools.mjs';

skipWithoutChromium();
const [webDir, replayPath, pngPath, longReplayPath] = process.argv.slice(2);
if (!longReplayPath) {
  console.error('usage: node page_theatre_test.mjs WEB_DIR REPLAY PNG LONG_REPLAY');
  process.exit(2);
}
const lastTick = (text) => Number(/^end (\d+)/m.exec(text)?.[1] ?? NaN);
const median = (values) => { const s = [...values].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };

const site = await serve(webDir);
const page = await Chromium.launch();
try {
  // Picks `file` in the page's file input, as the Open a replay button lets a player do.
  const pick = async (file) => {
    const { root } = await page.send('DOM.getDocument', {});
    const { nodeId } = await page.send('DOM.querySelector', { nodeId: root.nodeId, selector: '#replay-file' });
    if (!nodeId) fail('the page has no #replay-file input');
    await page.send('DOM.setFileInputFiles', { nodeId, files: [resolve(file)] });
  };
  // A left click at canvas pixel (x, y), through the canvas's place on the page.
  const click = async (x, y) => {
    const r = await page.rectOf('#canvas');
    const at = { x: r.x + (x + 0.5) * r.w / 640, y: r.y + (y + 0.5) * r.h / 360, button: 'left', clickCount: 1 };
    await page.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x: at.x, y: at.y });
    await page.send('Input.dispatchMouseEvent', Object.assign({ type: 'mousePressed' }, at));
    await page.send('Input.dispatchMouseEvent', Object.assign({ type: 'mouseReleased' }, at));
  };

  // 1. A replay from a file, at its last tick with the bar hidden, is the golden frame.
  await page.open(site.base + '?mute');
  await pick(replayPath);
  const end = lastTick(readFileSync(replayPath, 'latin1'));
  await page.waitFor('the theatre playing the picked replay', (s) => s.screen === 'replay' && s.tick > 0, 20);
  await page.press('KeyH');
  await page.press('End');
  await page.waitFor(`the theatre at tick ${end}`, (s) => s.tick === end, 10);
  await sleep(100);  // a frame drawn since
  await page.expectCanvas(pngPath);
  console.log(`PASS the picked ${replayPath} at tick ${end} in the theatre equals ${pngPath}, every byte`);

  // 1b. A replay file dropped on the page opens too (a drop event carrying the file, as a drag from
  // the desktop delivers it).
  await page.press('Escape');
  await page.waitFor('back from the theatre', (s) => s.screen !== 'replay', 5);
  const dropped = JSON.stringify(readFileSync(replayPath, 'latin1'));
  await page.evaluate(`(() => { const files = new DataTransfer();
    files.items.add(new File([${dropped}], 'dropped.replay'));
    document.dispatchEvent(new DragEvent('drop', { dataTransfer: files, bubbles: true, cancelable: true })); })()`);
  await page.waitFor('the theatre playing the dropped replay', (s) => s.screen === 'replay' && s.tick > 0, 20);
  console.log('PASS a replay dropped on the page plays in the theatre');

  // 2. Seeks by clicking the seek bar (its track is canvas row 328, columns 6 to 633), paused.
  await page.press('Escape');
  await page.waitFor('back from the theatre', (s) => s.screen !== 'replay', 5);
  const readFrom = await page.evaluate('performance.now()');
  await pick(longReplayPath);
  await page.waitFor('the theatre playing the long replay', (s) => s.screen === 'replay' && s.tick > 0, 30);
  // While the theatre reads the replay ahead (600 ticks a frame), each frame must still fit in 1/60 s.
  const reading = await page.evaluate(`Module.polarFrameTimes.filter((f) => f[0] >= ${readFrom}).map((f) => f[1])`);
  console.log(`frames while the theatre read ${longReplayPath} ahead and began: ${reading.length}, cost median ` +
    `${median(reading).toFixed(1)} ms, worst ${Math.max(...reading).toFixed(1)} ms (${reading.map((c) => c.toFixed(1)).join(" ")})`);
  if (median(reading) > 1000 / 60) fail('reading a replay ahead takes more than a 60 Hz frame');
  await page.press('Space');
  const rows = [];
  let seeks = (await page.probe()).seek.seeks;
  for (let i = 0; i < 40; ++i) {
    await click(6 + Math.floor(((i * 7919) % 628)), 328);
    const s = await page.waitFor('the seek reported', (p) => p.seek.seeks > seeks && p.seek.drawingMs > 0, 5);
    seeks = s.seek.seeks;
    rows.push(s.seek);
  }
  const part = (name) => rows.map((r) => r[name]);
  const whole = rows.map((r) => r.restoreMs + r.steppingMs + r.drawingMs);
  console.log(`seeks in chromium (${rows.length}, by clicks on the bar), ms: median / worst`);
  console.log(`  seek with its frame ${median(whole).toFixed(3)} / ${Math.max(...whole).toFixed(3)}`);
  for (const name of ['restoreMs', 'steppingMs', 'drawingMs'])
    console.log(`  ${name.replace('Ms', '').padEnd(18)} ${median(part(name)).toFixed(3)} / ${Math.max(...part(name)).toFixed(3)}`);
  console.log(`  ticks stepped      ${median(part('ticks'))} / ${Math.max(...part('ticks'))}`);
  if (Math.max(...part('ticks')) >= 60) fail('a seek stepped 60 ticks or more: the keyframes are not every 60');

  // 3. A game played in the page is kept in IndexedDB: after a reload the list plays it.
  await page.open(site.base + '?mute&lives=1&seed=3');
  // A setting changed in Options (the master volume, one step down) is kept over the reload too.
  for (const key of ['ArrowDown', 'ArrowDown', 'ArrowDown', 'Enter', 'ArrowLeft', 'Escape', 'ArrowUp', 'ArrowUp', 'ArrowUp'])
    await page.press(key);
  const settingsText = "(() => { try { return new TextDecoder().decode(FS.readFile('/data/polarcade/settings.json')); } catch (e) { return ''; } })()";
  const volumeIn = (text) => Number(/"master_volume":\s*(\d+)/.exec(text)?.[1] ?? NaN);
  const changedVolume = volumeIn(await page.evaluate(settingsText));
  if (!(changedVolume < 80)) fail(`Options did not save a master volume below the default 80 %: ${await page.evaluate(settingsText)}`);
  await page.press('Space');
  await page.waitFor('a game', (s) => s.screen === 'playing', 5);
  await sleep(1500);
  await page.press('Escape');
  await page.waitFor('the pause menu', (s) => s.screen === 'paused', 5);
  for (const key of ['ArrowDown', 'ArrowDown', 'ArrowDown', 'Enter']) await page.press(key);
  await page.waitFor('back on the title', (s) => s.screen === 'title', 5);
  await page.evaluate(`new Promise((resolve) => { Module.onDataSaved = resolve; })`);
  await page.open(site.base + '?mute&lives=2');  // a new address: a navigation waits for its page, a reload may not
  const keptVolume = volumeIn(await page.evaluate(settingsText));
  if (keptVolume !== changedVolume) fail(`the master volume was ${changedVolume} % before the reload, ${keptVolume} after`);
  console.log(`PASS the master volume set in Options (${keptVolume} %) is kept over a reload`);
  const kept = await page.evaluate(`FS.readdir('/data/polarcade/replays').filter((n) => n.endsWith('.replay'))`);
  if (kept.length < 1) fail(`no replay kept in IndexedDB after a reload: ${JSON.stringify(kept)}`);
  for (const key of ['ArrowDown', 'ArrowDown', 'Enter']) await page.press(key);
  await page.waitFor('the replay list', (s) => s.screen === 'replays' || s.screen === 'title', 5);
  await sleep(300);
  // The newest (the game just played) is exported as a download, byte for byte what is kept.
  const downloads = mkdtempSync(join(tmpdir(), 'polarcade-downloads-'));
  await page.send('Browser.setDownloadBehavior', { behavior: 'allow', downloadPath: downloads }, null);
  await page.press('KeyE');
  const newest = [...kept].sort().pop();
  const expected = Buffer.from(await page.evaluate(`btoa(String.fromCharCode.apply(null, FS.readFile('/data/polarcade/replays/${newest}')))`), 'base64');
  let downloaded = null;
  for (let waited = 0; !downloaded && waited < 5000; waited += 100) {
    const done = readdirSync(downloads).filter((n) => n.endsWith('.replay'));
    if (done.length) downloaded = readFileSync(join(downloads, done[0]));
    else await sleep(100);
  }
  rmSync(downloads, { recursive: true, force: true });
  if (!downloaded) fail('E on the replay list downloaded nothing');
  if (!downloaded.equals(expected)) fail(`the downloaded replay differs from the kept one (${downloaded.length} bytes, kept ${expected.length})`);
  console.log(`PASS E on the list downloads the newest replay, ${downloaded.length} bytes as kept`);
  await page.press('Enter');
  await page.waitFor('the kept game playing in the theatre', (s) => s.screen === 'replay' && s.tick > 30, 20);
  console.log(`PASS ${kept.length} replay(s) kept in IndexedDB across a reload; the list plays the newest`);
} finally {
  await page.close();
  site.close();
}

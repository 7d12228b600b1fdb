// The web page in a real browser: headless chromium over DevTools (devtools.mjs), against
// build-web/web/ served from 127.0.0.1. Usage: node page_test.mjs WEB_DIR REPLAY PNG TICK
// [SCREENSHOT.png [PHONE.png]] (the page on a desktop, and on a phone under three fingers).
// Checks, in order: the page's files gzip to 600 KB or less; the replay's frame after TICK drawn
// in the page equals PNG byte for byte; key presses start a game, thrust moves the ship and fire
// makes a bullet (with sound); a hidden page pauses the game and stops its sound, and only the
// player's input resumes it; the window's blur pauses too; a high score entered with the keys is
// still there after a reload; a corrupt stored table gives an empty one and a console message; a
// gamepad starts a game and moves the ship; on a phone's metrics a tap starts a game, three
// fingers turn, thrust and fire at once and hit a rock, a swipe, a long press and a double tap
// neither scroll, zoom, select nor pause, the pause button pauses and resumes, and a tap on the
// pause screen's RESUME resumes; leaving a game asks first, leaving the title does not; offline,
// the page loads from its service worker and plays; with the CPU throttled 4x a busy game keeps
// up (its frame times printed); the web render benchmark (bench/ beside the page) prints its frame
// times and finds its kernels' bytes equal. Exits 1 with the reason when a check fails, 77 when
// there is no chromium.
import { readdirSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { Chromium, fail, serve, skipWithoutChromium, sleep } from './devtools.mjs';

skipWithoutChromium();
const [webDir, replayPath, pngPath, tickText, screenshotPath, phoneShotPath] = process.argv.slice(2);
const tick = Number(tickText);


const site = await serve(webDir);
const base = site.base;
const browser = await Chromium.launch();
const evaluate = (expression) => browser.evaluate(expression), probe = () => browser.probe();
const open = (url) => browser.open(url), send = (method, params, sessionId) => browser.send(method, params, sessionId);
const waitFor = (what, test, seconds) => browser.waitFor(what, test, seconds);
const key = (type, code) => browser.key(type, code), press = (code) => browser.press(code);
const touch = (type, points) => browser.touch(type, points), tap = (x, y) => browser.tap(x, y);
const rectOf = (selector) => browser.rectOf(selector);
// The game's sound devices as "state/playing" (WebAudio's state; whether the game feeds it).
const sound = () => evaluate("Module.polarAudio ? Module.polarAudio.filter((d) => d).map((d) => d.context.state + '/' + d.playing).join(',') : 'none'");

try {
  // 0. The first download: every file of the page (the web render benchmark's bench/ aside),
  // gzipped at level 9, within issue 28's 600 KB.
  const bundle = readdirSync(webDir).filter((name) => statSync(join(webDir, name)).isFile())
    .map((name) => [name, gzipSync(readFileSync(join(webDir, name)), { level: 9 }).length]);
  const bundleBytes = bundle.reduce((sum, [, bytes]) => sum + bytes, 0);
  console.log(`bundle gzipped: ${bundle.map(([name, bytes]) => `${name} ${bytes}`).join(', ')}; ${bundleBytes} bytes in all`);
  if (bundleBytes > 600000) fail(`the page's files gzip to ${bundleBytes} bytes, over the 600 KB budget`);
  console.log(`PASS the bundle gzips to ${(bundleBytes / 1000).toFixed(0)} KB of 600`);

  // 1. The replay's frame after `tick`, drawn in the page, against the native renderer's PNG.
  const firstFrame = await open(base + '?mute');
  console.log(`first frame ${firstFrame.toFixed(0)} ms after the navigation started`);
  const replayText = readFileSync(replayPath, 'latin1');
  await evaluate(`FS.writeFile('/tmp/golden.replay', ${JSON.stringify(replayText)}); 0`);
  const shown = await evaluate(`Module.ccall('polar_web_show_replay', 'number', ['string', 'number'], ['/tmp/golden.replay', ${tick}])`);
  if (shown !== 0) fail(`the page could not play ${replayPath}:\n${browser.consoleLines.join('\n')}`);
  const golden = await browser.expectCanvas(pngPath);
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
  const audio = await sound();
  if (audio !== 'running/true') fail(`the game's sound is not playing: its device is ${audio} (state/fed)`);
  console.log(`PASS sound: WebAudio is ${audio}`);
  if (screenshotPath) {
    const { data } = await send('Page.captureScreenshot', { format: 'png' });
    writeFileSync(screenshotPath, Buffer.from(data, 'base64'));
    console.log(`saved a screenshot of the page to ${screenshotPath}`);
  }

  // 2b. The page hidden (another tab in front): its frames stop and its sound is suspended at
  // once; back in front, the first frame shows the pause screen before any tick, it stays paused
  // until the player's input, and Space on RESUME plays on, with sound.
  await key('keyUp', 'Space');
  const other = await send('Target.createTarget', { url: 'about:blank' }, null);
  const hiddenSince = Date.now();
  while ((await evaluate('document.visibilityState')) !== 'hidden')
    if (Date.now() - hiddenSince > 5000) fail('the page is not hidden behind another tab'); else await sleep(20);
  const hiddenAt = (await probe()).tick, hiddenSound = await sound();
  if (!hiddenSound.startsWith('suspended')) fail(`the hidden page's sound is ${hiddenSound}; expected suspended`);
  await sleep(300);
  if ((await probe()).tick !== hiddenAt) fail('the game went on ticking in a hidden page');
  await send('Target.closeTarget', { targetId: other.targetId }, null);
  await send('Target.activateTarget', { targetId: browser.targetId }, null);
  const away = await waitFor('the pause screen back in front', (s) => s.screen === 'paused', 5);
  if (away.tick !== hiddenAt) fail(`the game ticked from ${hiddenAt} to ${away.tick} before it paused`);
  await sleep(400);
  const back = await probe(), backSound = await sound();
  if (back.screen !== 'paused' || back.tick !== away.tick)
    fail(`back in front with no input the game shows ${back.screen} at tick ${back.tick}; expected paused at ${away.tick}`);
  if (!backSound.endsWith('/false')) fail(`the paused game feeds its sound: ${backSound}`);
  await press('Space');
  await waitFor('play again after Space on RESUME', (s) => s.screen === 'playing' && s.tick > away.tick, 5);
  const resumedSound = await sound();
  if (resumedSound !== 'running/true') fail(`after resuming, the sound is ${resumedSound}; expected running/true`);
  console.log(`PASS a hidden page: frames and sound stopped at tick ${hiddenAt} (${hiddenSound}), the game came back paused (${backSound}) and Space resumed it (${resumedSound})`);
  // The window losing the focus with the page in sight (another window in front: the event that
  // window sends) pauses too.
  await evaluate("window.dispatchEvent(new FocusEvent('blur')); 0");
  await waitFor('the pause screen after the window lost the focus', (s) => s.screen === 'paused', 3);
  await press('Space');
  await waitFor('play again after Space on RESUME', (s) => s.screen === 'playing', 5);
  console.log('PASS the window losing the focus paused the game, and Space resumed it');
  await key('keyDown', 'Space');

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
  // Enter on the name shows the table with the new score in it (not the title).
  await waitFor('the table with the new score', (s) => s.screen === 'high-scores' && s.highScores.some((e) => e.score === over.score), 5);
  await evaluate(`new Promise((resolve) => { Module.onDataSaved = resolve; })`);
  browser.dialogs.length = 0;
  await open(base + '?mute');
  if (browser.dialogs.length) fail(`leaving the title asked first (${browser.dialogs}): only a game in progress should`);
  const reloaded = await waitFor('the high score after a reload', (s) => s.highScores.length > 0, 5);
  if (!reloaded.highScores.some((e) => e.name === 'AAA' && e.score === over.score))
    fail(`after a reload the table is ${JSON.stringify(reloaded.highScores)}; expected AAA ${over.score}`);
  console.log(`PASS the high score AAA ${over.score} was kept over a reload`);

  // 4. A corrupt stored table: an empty table and a console message, the game running on.
  await evaluate(`FS.writeFile('/data/polarcade/highscores.json', '{"format": 1, "scores": [{'); 0`);
  await evaluate(`new Promise((resolve) => { Module.onDataSaved = resolve; })`);
  browser.consoleLines = [];
  await open(base + '?mute');
  const fresh = await waitFor('an empty table after a corrupt one', (s) => s.screen === 'title' && s.tick > 10, 5);
  if (fresh.highScores.length !== 0) fail(`a corrupt table was read as ${JSON.stringify(fresh.highScores)}`);
  if (!browser.consoleLines.some((line) => line.includes('highscores.json')))
    fail(`no console message names the corrupt table; the console says:\n${browser.consoleLines.join('\n')}`);
  console.log(`PASS a corrupt table: an empty one, and the console says: ${browser.consoleLines.find((l) => l.includes('highscores.json'))}`);
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
  await send('Emulation.setDeviceMetricsOverride', { width: 412, height: 915, deviceScaleFactor: 2.625, mobile: true });
  await send('Emulation.setTouchEmulationEnabled', { enabled: true, maxTouchPoints: 5 });
  await open(base + '?lives=3&seed=3');
  // The first touch only brings the touch controls, which take room from the canvas: it never
  // reaches the game (on the title it would choose the row under the finger). Then a tap on the
  // title's first row, PLAY (canvas rows 136-158 of 360, centred: game/app/screens/title_screen.cpp),
  // where it is once they are shown.
  let picture = await rectOf('#canvas');
  await tap(picture.x + picture.w * 320 / 640, picture.y + picture.h * 147 / 360);
  await sleep(300);
  const afterFirst = await probe();
  if (afterFirst.screen !== 'title') fail(`the touch that showed the controls reached the game: it opened "${afterFirst.screen}"`);
  picture = await rectOf('#canvas');
  await tap(picture.x + picture.w * 320 / 640, picture.y + picture.h * 147 / 360);
  const touchStart = await waitFor('a game started by a tap on the game', (s) => s.screen === 'playing' && s.ship, 5);
  if ((await evaluate('document.body.dataset.device')) !== 'touch') fail('the first touch did not show the touch controls');
  // Held upright, the phone's height is used: the game at the top of the screen, no black band
  // above or below it, the touch pads from under the bar down to the thumbs.
  const steerPad = await rectOf('#steer');
  if (picture.y > 1 || steerPad.y - (picture.y + picture.h) > 140 || steerPad.y + steerPad.h < 915 - 24)
    fail(`upright, the game is at y ${picture.y} (${picture.w}x${picture.h}) and the pad from ${steerPad.y} to ${steerPad.y + steerPad.h} of 915; expected the game at the top and the pad from under its bar to the bottom`);
  console.log(`PASS upright: the game at the top (${picture.w}x${picture.h}), the pads from y ${steerPad.y} to ${steerPad.y + steerPad.h} of 915`);
  const [left, thrust, fire] = await Promise.all(['[data-key=ArrowLeft]', '[data-key=ArrowUp]', '[data-key=Space]'].map(rectOf));
  await touch('touchStart', [{ x: left.cx, y: left.cy, id: 1 }, { x: thrust.cx, y: thrust.cy, id: 2 }, { x: fire.cx, y: fire.cy, id: 3 }]);
  const together = await waitFor('the ship moved, turned and fired under three fingers', (s) => s.ship && s.bullets > 0 &&
    Math.hypot(s.ship[0] - touchStart.ship[0], s.ship[1] - touchStart.ship[1]) > 5 && Math.abs(s.heading - touchStart.heading) > 0.3, 5);
  const held = await evaluate("document.querySelectorAll('.touch-controls .held').length");
  if (held !== 3) fail(`three fingers hold ${held} controls`);
  if (phoneShotPath) {
    // In CSS pixels (412x915), as the phone's screen looks at arm's length.
    const clip = { x: 0, y: 0, width: 412, height: 915, scale: 1 / 2.625 };
    const { data } = await send('Page.captureScreenshot', { format: 'png', clip });
    writeFileSync(phoneShotPath, Buffer.from(data, 'base64'));
    console.log(`saved a screenshot of the page on a phone to ${phoneShotPath}`);
  }
  console.log(`PASS three fingers at once: the ship moved from (${touchStart.ship.map((v) => v.toFixed(1))}) to (${together.ship.map((v) => v.toFixed(1))}), turned ${(together.heading - touchStart.heading).toFixed(2)} rad, ${together.bullets} bullet(s)`);
  await touch('touchEnd', [{ x: thrust.cx, y: thrust.cy, id: 2 }]);  // the thrust finger lifted, the others held
  const heldAfterLift = await evaluate("Array.from(document.querySelectorAll('.touch-controls .held')).map((e) => e.dataset.key).join(',')");
  if (heldAfterLift !== 'ArrowLeft,Space') fail(`with the thrust finger lifted the controls held are ${heldAfterLift}; expected ArrowLeft,Space`);
  const hit = await waitFor('a rock hit by turning and firing', (s) => s.score > 0, 60);
  await touch('touchEnd', []);
  console.log(`PASS a rock hit by touch: score ${hit.score}, with the thrust finger lifted and ${heldAfterLift} held`);
  // A swipe across the game, a long press and a double tap on the legend: the page stays put,
  // nothing is selected, and the game plays on (a tap beside the canvas is no looking away).
  await touch('touchStart', [{ x: picture.x + 20, y: picture.cy, id: 4 }]);
  for (let i = 1; i <= 6; ++i) { await touch('touchMove', [{ x: picture.x + 20 + i * 40, y: picture.cy + i * 30, id: 4 }]); await sleep(16); }
  await touch('touchEnd', []);
  const legend = await rectOf('.legend.touch');
  await touch('touchStart', [{ x: legend.cx, y: legend.cy, id: 5 }]);
  await sleep(900);
  await touch('touchEnd', []);
  for (let i = 0; i < 2; ++i) {
    await touch('touchStart', [{ x: legend.cx, y: legend.cy, id: 6 + i }]);
    await sleep(30);
    await touch('touchEnd', []);
    await sleep(80);
  }
  await sleep(400);  // a double tap's zoom would have begun by now
  const still = await evaluate('[window.scrollX, window.scrollY, window.visualViewport.scale, String(getSelection())].join(" ")');
  if (still !== '0 0 1 ') fail(`a swipe, a long press and a double tap moved the page: scroll, zoom and selection are ${still}`);
  const playedOn = await probe();
  if (playedOn.screen !== 'playing') fail(`a swipe, a long press and a double tap left the game ${playedOn.screen}; expected playing`);
  console.log('PASS a swipe, a long press and a double tap: no scroll, no zoom, nothing selected, the game plays on');
  // The pause button: a tap shows the game's pause screen and stops its sound; a second tap plays on.
  const pauseButton = await rectOf('#touch-pause');
  await tap(pauseButton.cx, pauseButton.cy);
  const tapped = await waitFor('the pause screen after a tap on the pause button', (s) => s.screen === 'paused', 3);
  const pausedSound = await sound();
  if (!pausedSound.endsWith('/false')) fail(`the paused game still feeds its sound: ${pausedSound}`);
  await sleep(300);
  if ((await probe()).tick !== tapped.tick) fail('the game went on ticking behind its pause screen');
  await tap(pauseButton.cx, pauseButton.cy);
  await waitFor('play again after a second tap on the pause button', (s) => s.screen === 'playing' && s.tick > tapped.tick, 3);
  console.log(`PASS the pause button: a tap paused the game at tick ${tapped.tick} (sound ${pausedSound}), a second tap resumed it`);
  // The pause screen's menu by tapping: RESUME, its first row (rows 150-172 of 360, centred:
  // game/app/screens/paused_screen.cpp).
  await tap(pauseButton.cx, pauseButton.cy);
  const pausedAgain = await waitFor('the pause screen after a third tap on the pause button', (s) => s.screen === 'paused', 3);
  picture = await rectOf('#canvas');
  await tap(picture.x + picture.w * 320 / 640, picture.y + picture.h * 161 / 360);
  await waitFor('play again after a tap on RESUME', (s) => s.screen === 'playing' && s.tick > pausedAgain.tick, 3);
  console.log('PASS a tap on the pause screen\'s RESUME played on');

  // 7. Leaving the game in progress asks first (the test's dialog handler says leave). Offline:
  // the service worker has kept the bundle since the first visit; with the network gone
  // (emulated offline, and the server hanging up on whatever still reaches it) the page loads
  // again and a game plays.
  const kept = await evaluate(`navigator.serviceWorker.ready.then(() => caches.open('polarcade')).then((c) => c.keys())
    .then((keys) => [...new Set(keys.map((r) => new URL(r.url).pathname))].sort().join(' '))`);
  await send('Network.enable');
  await send('Network.emulateNetworkConditions', { offline: true, latency: 0, downloadThroughput: -1, uploadThroughput: -1 });
  site.offline = true;
  browser.dialogs.length = 0;
  const offlineFrame = await open(base + '?lives=3&seed=3');  // leaves the game in progress
  if (!browser.dialogs.includes('beforeunload')) fail('leaving a game in progress did not ask first');
  await press('Space');
  await waitFor('a game played offline', (s) => s.screen === 'playing' && s.tick > 30, 5);
  if (await evaluate('navigator.onLine')) fail('the emulated network is still online');
  site.offline = false;
  await send('Network.emulateNetworkConditions', { offline: false, latency: 0, downloadThroughput: -1, uploadThroughput: -1 });
  console.log(`PASS offline: the page loaded from the service worker's cache (${kept}), first frame at ${offlineFrame.toFixed(0)} ms, and a game played; leaving the game asked first`);

  // 8. Frame times with the CPU throttled 4x (a low-end machine) in a busy game: the ship turns
  // and fires for 2.5 s while the wave splits into fragments. Each frame's cost is the game's work
  // in it (Module.polarFrameTimes: input, fixed steps, drawing, the present).
  await send('Emulation.clearDeviceMetricsOverride');
  await send('Emulation.setTouchEmulationEnabled', { enabled: false });
  await send('Emulation.setCPUThrottlingRate', { rate: 4 });
  await open(base + '?mute&lives=99&seed=3');
  await press('Space');
  await waitFor('a game for the throttled frames', (s) => s.screen === 'playing' && s.ship, 5);
  await key('keyDown', 'Space');
  await key('keyDown', 'ArrowLeft');
  await sleep(500);
  const [from, fromTick] = [await evaluate('performance.now()'), (await probe()).tick];
  await sleep(2500);
  const [to, toTick] = [await evaluate('performance.now()'), (await probe()).tick];
  await key('keyUp', 'ArrowLeft');
  await key('keyUp', 'Space');
  await send('Emulation.setCPUThrottlingRate', { rate: 1 });
  const costs = (await evaluate(`Module.polarFrameTimes.filter((f) => f[0] >= ${from} && f[0] <= ${to}).map((f) => f[1])`)).sort((a, b) => a - b);
  const median = costs[Math.floor(costs.length / 2)], p99 = costs[Math.min(costs.length - 1, Math.floor(costs.length * 0.99))];
  const worst = costs[costs.length - 1], ticksPerSecond = (toTick - fromTick) / ((to - from) / 1000);
  console.log(`frame cost with the CPU throttled 4x: median ${median.toFixed(1)} ms, 99th percentile ${p99.toFixed(1)} ms, worst ${worst.toFixed(1)} ms ` +
    `over ${costs.length} frames in ${((to - from) / 1000).toFixed(1)} s (${(costs.length / ((to - from) / 1000)).toFixed(1)} a second); the game stepped ${ticksPerSecond.toFixed(1)} ticks a second`);
  // Keeping up: the median frame's work fits a 60 Hz frame (16.7 ms), and the fixed step stays
  // with the clock (at least 57 of its 60 ticks a second). Single slow frames are printed, not
  // held: on this shared 2-core machine another build's burst makes them.
  if (median > 1000 / 60) fail(`with the CPU throttled 4x the median frame takes ${median.toFixed(1)} ms, over a 60 Hz frame`);
  if (ticksPerSecond < 57) fail(`with the CPU throttled 4x the game steps only ${ticksPerSecond.toFixed(1)} ticks a second of its 60`);
  console.log('PASS with the CPU throttled 4x the game keeps up');

  // 7. The web render benchmark (build-web/web/bench/): the render benchmark's 500-sprite scene,
  // scalar against SIMD128, timed in this browser; its kernels must draw the same bytes.
  browser.consoleLines = [];
  await send('Page.navigate', { url: base + 'bench/polarcade-render-bench.html' });
  const benchStart = Date.now();
  while (!browser.consoleLines.some((line) => line.startsWith('web render bench done') || line.startsWith('FAIL'))) {
    if (Date.now() - benchStart > 120000) fail(`the web render benchmark did not finish in 120 s:\n${browser.consoleLines.join('\n')}`);
    await sleep(100);
  }
  for (const line of browser.consoleLines) console.log('  ' + line);
  if (browser.consoleLines.some((line) => line.startsWith('FAIL'))) fail('the web render benchmark\'s kernels drew different bytes');
  console.log('PASS the web render benchmark ran in chromium and its kernels drew the same bytes');

  if (browser.pageErrors.length) fail(`the page threw:\n${browser.pageErrors.join('\n')}`);
} catch (error) {
  if (!process.exitCode) console.error('FAIL: ' + error.message);
  process.exitCode = 1;
} finally {
  await browser.close();
  site.close();
}

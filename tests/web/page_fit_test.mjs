// The page's layout on every screen, in headless chromium over DevTools: the six viewports of
// issue 28 (phones in portrait and landscape, a laptop window, a desktop) at device scale factors
// 1, 2 and 3, each laid out for a keyboard and for touch (the touch controls shown). In each the
// canvas must be inside the viewport, keep the game's 16:9 to a device pixel, fill its room along
// one side (the room the legend, the buttons and the touch controls leave), and overlap none of
// them; the legend, the buttons and the touch controls must be inside the viewport too (nothing
// below the fold). Prints a table of the canvas's sizes; with SHOT_DIR, saves a screenshot of
// each viewport and scale factor, laid out for the device that screen comes with.
// Usage: node page_fit_test.mjs WEB_DIR [SHOT_DIR]. Exits 1 with the reason when a check fails,
// 77 when there is no chromium.
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { Chromium, fail, serve, skipWithoutChromium } from './devtools.mjs';

skipWithoutChromium();
const [webDir, shotDir] = process.argv.slice(2);
if (!webDir) {
  console.error('usage: node page_fit_test.mjs WEB_DIR [SHOT_DIR]');
  process.exit(2);
}

// width, height, and whether it is a phone (mobile viewport, touch first).
const viewports = [[360, 640, true], [412, 915, true], [740, 360, true], [915, 412, true], [1366, 650, false], [1920, 1080, false]];
const scales = [1, 2, 3];
// The controls' 8 px margins on both sides and the rounding to whole device pixels: room the
// canvas may leave along the side it fills.
const slackLimit = 20;

// The layout's rectangles, measured in the page: the canvas, and every visible thing it must not
// cover (the legend's entries, the buttons, the status line, the touch controls).
const measure = `new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(() => {
  const box = (e) => { const r = e.getBoundingClientRect(); return { x: r.x, y: r.y, r: r.right, b: r.bottom }; };
  const shown = (e) => { const r = e.getBoundingClientRect(); return r.width > 0 && r.height > 0 && getComputedStyle(e).visibility !== 'hidden'; };
  const parts = [...document.querySelectorAll('#bar li, #bar button, #status, .touch-controls, .touch-controls [data-key]')].filter(shown)
    .map((e) => Object.assign(box(e), { name: e.id || e.textContent.trim().slice(0, 24), scrolls: e.scrollWidth > e.clientWidth + 1 || e.scrollHeight > e.clientHeight + 1 }));
  resolve({ W: innerWidth, H: innerHeight, dpr: devicePixelRatio, device: document.body.dataset.device,
            canvas: box(document.getElementById('canvas')), parts });
})))`;

// What is wrong with a layout, or '' when nothing is.
function check(m) {
  const c = m.canvas, w = c.r - c.x, h = c.b - c.y, e = 0.01;
  if (c.x < -e || c.y < -e || c.r > m.W + e || c.b > m.H + e) return `the canvas ${JSON.stringify(c)} is cut off by the ${m.W}x${m.H} viewport`;
  if (Math.abs(h - w * 9 / 16) > 1 / m.dpr + e) return `the canvas is ${w.toFixed(2)}x${h.toFixed(2)}: not 16:9 to a device pixel`;
  for (const p of m.parts) {
    if (p.x < -e || p.y < -e || p.r > m.W + e || p.b > m.H + e) return `"${p.name}" ${JSON.stringify(p)} is outside the ${m.W}x${m.H} viewport`;
    if (p.scrolls) return `"${p.name}" does not hold its own content (it overflows ${JSON.stringify(p)})`;
    const across = Math.min(p.r, c.r) - Math.max(p.x, c.x), down = Math.min(p.b, c.b) - Math.max(p.y, c.y);
    if (across > 0.5 && down > 0.5) return `"${p.name}" covers the canvas (${across.toFixed(1)}x${down.toFixed(1)} px)`;
  }
  // The room beside the canvas on each side: up to the viewport's edge or the nearest part that
  // faces that side.
  const facing = (p, alongX) => alongX ? p.b > c.y && p.y < c.b : p.r > c.x && p.x < c.r;
  let left = c.x, right = m.W - c.r, top = c.y, bottom = m.H - c.b;
  for (const p of m.parts) {
    if (facing(p, true) && p.r <= c.x + e) left = Math.min(left, c.x - p.r);
    if (facing(p, true) && p.x >= c.r - e) right = Math.min(right, p.x - c.r);
    if (facing(p, false) && p.b <= c.y + e) top = Math.min(top, c.y - p.b);
    if (facing(p, false) && p.y >= c.b - e) bottom = Math.min(bottom, p.y - c.b);
  }
  const slack = Math.min(left + right, top + bottom);
  if (slack > slackLimit) return `the canvas (${w.toFixed(1)}x${h.toFixed(1)}) leaves ${(left + right).toFixed(1)} px across and ${(top + bottom).toFixed(1)} px down unused: it could be larger`;
  return '';
}

const site = await serve(webDir);
const browser = await Chromium.launch();
if (shotDir) mkdirSync(shotDir, { recursive: true });
try {
  await browser.send('Emulation.setTouchEmulationEnabled', { enabled: true, maxTouchPoints: 5 });
  await browser.send('Emulation.setDeviceMetricsOverride', { width: 412, height: 915, deviceScaleFactor: 1, mobile: true });
  await browser.open(site.base + '?mute');
  // The device in use is the last one the page saw: a touch (on the legend, which does nothing),
  // or a key (Shift, which the title ignores).
  const use = async (device) => {
    if (device === 'touch') {
      const legend = await browser.rectOf('#bar');
      await browser.tap(legend.x + 2, legend.y + 2);
    } else {
      await browser.send('Input.dispatchKeyEvent', { type: 'keyDown', code: 'ShiftLeft', key: 'Shift', windowsVirtualKeyCode: 16 });
      await browser.send('Input.dispatchKeyEvent', { type: 'keyUp', code: 'ShiftLeft', key: 'Shift', windowsVirtualKeyCode: 16 });
    }
    const now = await browser.evaluate('document.body.dataset.device');
    if (now !== device) fail(`a ${device === 'touch' ? 'touch' : 'key'} left the page laid out for ${now}`);
  };
  console.log('viewport   scale  keyboard: canvas (scale)   touch: canvas (scale)');
  let checked = 0, shots = 0;
  for (const deviceScaleFactor of scales) {
    for (const [width, height, phone] of viewports) {
      await browser.send('Emulation.setDeviceMetricsOverride', { width, height, deviceScaleFactor, mobile: phone });
      const cells = {};
      // The screen's own device last, so the screenshot shows it.
      for (const device of phone ? ['keyboard', 'touch'] : ['touch', 'keyboard']) {
        await use(device);
        const m = await browser.evaluate(measure);
        if (m.W !== width || m.H !== height || m.dpr !== deviceScaleFactor)
          fail(`the page sees ${m.W}x${m.H} at ${m.dpr}, not ${width}x${height} at ${deviceScaleFactor}`);
        const wrong = check(m);
        if (wrong) fail(`${width}x${height} at scale ${deviceScaleFactor}, laid out for ${device}: ${wrong}`);
        const w = m.canvas.r - m.canvas.x, h = m.canvas.b - m.canvas.y;
        cells[device] = `${w.toFixed(1)}x${h.toFixed(1)} (${(w / 640).toFixed(2)})`;
        ++checked;
      }
      console.log(`${`${width}x${height}`.padEnd(10)} ${String(deviceScaleFactor).padStart(5)}  ${cells.keyboard.padEnd(24)} ${cells.touch}`);
      if (shotDir) {
        const { data } = await browser.send('Page.captureScreenshot', { format: 'png' });
        writeFileSync(join(shotDir, `${width}x${height}@${deviceScaleFactor}.png`), Buffer.from(data, 'base64'));
        ++shots;
      }
    }
  }
  console.log(`PASS the canvas fits, whole and 16:9, and covers nothing in ${checked} layouts (${viewports.length} viewports x ${scales.length} scales x keyboard and touch)`);
  if (shotDir) console.log(`saved ${shots} screenshots to ${shotDir}`);
  if (browser.pageErrors.length) fail(`the page threw:\n${browser.pageErrors.join('\n')}`);
} catch (error) {
  if (!process.exitCode) console.error('FAIL: ' + error.message);
  process.exitCode = 1;
} finally {
  await browser.close();
  site.close();
}

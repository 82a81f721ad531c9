import { startBrowser, stopBrowser, openExercise, nextRender } from './common.mjs';
const browser = await startBrowser();
const page = await browser.newPage();
const o = 'http://127.0.0.1:18471';
await openExercise(page, o, 'id=vib-sdof-forced');
const rows = [];
for (let i = 0; i < 8; i++) {
  await page.fill('#p-k', String(101 + i));
  const done = nextRender(page);
  await page.press('#p-k', 'Enter');
  const { seq } = await done;
  rows.push(await page.evaluate((s) => {
    const m = (n) => performance.getEntriesByName(`mm-${n}-${s}`)[0].startTime;
    return [m('answer') - m('solve'), m('drawn') - m('answer')].map((x) => x.toFixed(1)).join(' / ');
  }, seq));
}
console.log('fetch / draw ms:', rows.join(', '));
await page.evaluate(() => console.profile && 0);
// a JS profile of one redraw
const cdp = await page.context().newCDPSession(page);
await cdp.send('Profiler.enable');
await cdp.send('Profiler.setSamplingInterval', { interval: 100 });
await cdp.send('Profiler.start');
for (let i = 0; i < 5; i++) { await page.fill('#p-k', String(201 + i)); const d = nextRender(page); await page.press('#p-k', 'Enter'); await d; }
const { profile } = await cdp.send('Profiler.stop');
const self = new Map();
const byId = new Map(profile.nodes.map((n) => [n.id, n]));
const dt = profile.timeDeltas; let k = 0;
for (const id of profile.samples) { const n = byId.get(id); const key = `${n.callFrame.functionName || '(anon)'} ${n.callFrame.url.split('/').pop()}:${n.callFrame.lineNumber}`; self.set(key, (self.get(key) || 0) + (dt[k++] || 0) / 1000); }
console.log([...self.entries()].sort((a, b) => b[1] - a[1]).slice(0, 20).map(([k2, v]) => `${v.toFixed(1)} ${k2}`).join('\n'));
await stopBrowser(browser);

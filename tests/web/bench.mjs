// bench.mjs — in the browser, measured by the page's own clock
// (performance marks, no test-driver round trips):
//   first plot   navigation start → the first answer drawn and painted
//                (median of 7 loads of vib-sdof-forced, each a new query)
//   redraw       Enter in a field → the new answer drawn and painted
//                (median of 20; Enter skips the typing debounce)
// with each split into the wait for the answer (network and server) and the
// page's own work (parse, draw, lay out).  Goals: first plot < 300 ms,
// redraw < 50 ms.
import { loadavg } from 'node:os';
import { nextRender, openExercise, startBrowser, startServer, stopBrowser, stopServer } from './common.mjs';

const median = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];
const painted = (page, seq) => page.waitForFunction((s) => performance.getEntriesByName(`mm-painted-${s}`).length, seq);
const marks = (page, seq) => page.evaluate((s) => {
  const m = (n) => (performance.getEntriesByName(`mm-${n}-${s}`)[0] || {}).startTime;
  return { solve: m('solve'), answer: m('answer'), drawn: m('drawn'), painted: m('painted') };
}, seq);

let server, browser;
try {
  server = await startServer();
  browser = await startBrowser();
  const page = await browser.newPage();
  await openExercise(page, server.origin, 'id=vib-sdof-forced');          // warm the caches

  const loads = [], loadWait = [];
  for (let i = 0; i < 7; i++) {
    await openExercise(page, server.origin, `id=vib-sdof-forced&x0=0.00${i + 1}`);
    await painted(page, 1);
    const m = await marks(page, 1);
    loads.push(m.painted);
    loadWait.push(m.answer);
  }

  const redraws = [], waits = [], work = [];
  for (let i = 0; i < 20; i++) {
    await page.fill('#p-k', String(100 + i + 1));
    await page.evaluate(() => document.querySelector('#p-k').addEventListener('keydown', () => { window.zzKey = performance.now(); }, { once: true }));
    const done = nextRender(page);
    await page.press('#p-k', 'Enter');
    const { seq } = await done;
    await painted(page, seq);
    const m = await marks(page, seq);
    const key = await page.evaluate(() => window.zzKey);
    redraws.push(m.painted - key);
    waits.push(m.answer - m.solve);
    work.push(m.painted - m.answer);
  }
  const f = (x) => x.toFixed(0);
  console.log(`browser: load average ${loadavg().map((x) => x.toFixed(1)).join(' ')} on ${(await import('node:os')).cpus().length} cores (a busy machine stretches every figure below)`);
  console.log(`browser: first plot after navigation  median ${f(median(loads))} ms of 7   (goal < 300 ms; the answer arrived at ${f(median(loadWait))} ms)`);
  console.log(`browser: input change to redrawn plot median ${median(redraws).toFixed(1)} ms of 20  (goal < 50 ms; waiting for the answer ${median(waits).toFixed(1)} ms, drawing ${median(work).toFixed(1)} ms)`);
} finally {
  await stopBrowser(browser);
  await stopServer(server);
}

// dev_figs.mjs — screenshots of every figure of some exercises (for looking).
import { chromium } from 'playwright-core';
const [origin, out, w, ...ids] = process.argv.slice(2);
const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: ['--no-sandbox', '--disable-gpu'] });
const page = await browser.newPage({ viewport: { width: Number(w), height: 900 }, reducedMotion: 'reduce' });
page.on('pageerror', (e) => console.log('PAGEERROR', e.message));
page.on('console', (m) => { if (m.type() === 'error') console.log('CONSOLE', m.text()); });
for (const id of ids) {
  await page.goto(`${origin}/exercise.html?id=${id}`);
  await page.waitForFunction(() => document.documentElement.dataset.rendered, null, { timeout: 10000 });
  const figs = await page.$$('figure.plot, figure.anim');
  let i = 0;
  for (const f of figs) await f.screenshot({ path: `${out}/${id}-${i++}.png` });
  console.log(id, figs.length);
}
await browser.close();

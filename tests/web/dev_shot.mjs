// dev_shot.mjs — a screenshot of one page, for looking (not a test).
//   node tests/web/dev_shot.mjs ORIGIN 'id=vib-sdof-forced' out.png [width height] [full]
import { chromium } from 'playwright-core';
const [origin, query, out, w = '1280', h = '800', full] = process.argv.slice(2);
const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: ['--no-sandbox', '--disable-gpu'] });
const page = await browser.newPage({ viewport: { width: Number(w), height: Number(h) }, reducedMotion: 'reduce' });
page.on('pageerror', (e) => console.log('PAGEERROR', e.message));
page.on('console', (m) => { if (m.type() === 'error' || m.type() === 'warning') console.log('CONSOLE', m.text()); });
const url = query.startsWith('/') ? origin + query : `${origin}/exercise.html?${query}`;
await page.goto(url);
await page.waitForFunction(() => document.documentElement.dataset.rendered || document.documentElement.dataset.ready, null, { timeout: 10000 }).catch((e) => console.log('TIMEOUT', e.message));
await page.waitForFunction(() => document.documentElement.dataset.typeset || document.documentElement.dataset.ready, null, { timeout: 10000 }).catch(() => {});
if (process.env.FOCUS) { await page.focus(process.env.FOCUS); await page.waitForTimeout(300); }
await page.screenshot({ path: out, fullPage: !!full });
await browser.close();

// dev_el.mjs — screenshots of some elements of a page (for looking).
import { chromium } from 'playwright-core';
const [origin, query, out, w, ...sels] = process.argv.slice(2);
const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: ['--no-sandbox', '--disable-gpu'] });
const page = await browser.newPage({ viewport: { width: Number(w), height: 900 }, reducedMotion: 'reduce' });
page.on('pageerror', (e) => console.log('PAGEERROR', e.message));
await page.goto(`${origin}/exercise.html?${query}`);
await page.waitForFunction(() => document.documentElement.dataset.rendered, null, { timeout: 10000 });
await page.waitForTimeout(300);
let i = 0;
for (const s of sels) { const e = await page.$(s); if (e) await e.screenshot({ path: `${out}-${i++}.png` }); else console.log('none', s); }
await browser.close();

// Drives `chatsim serve` in headless Chromium (Debian's, through playwright-core): types a
// command, waits for the rendered round, and takes a screenshot.
//   node chat_page.mjs URL SCREENSHOT.png "command"
import { chromium } from 'playwright-core';

const [url, shot, command] = process.argv.slice(2);
const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
         '--disable-component-update', '--disable-sync'],
});
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
  await page.goto(url);
  await page.fill('#command', command);
  await page.click('#send');
  await page.waitForSelector('.msg.system, .msg.error', { timeout: 300000 });
  const failed = await page.$('.msg.error');
  if (!failed) {
    await page.waitForFunction(() => {
      const img = document.getElementById('frame');
      return img.complete && img.naturalWidth > 0;
    }, null, { timeout: 60000 });
  }
  await page.screenshot({ path: shot });
  const log = await page.textContent('#log');
  const frame = await page.$eval('#frame', (img) => ({ src: img.getAttribute('src'), width: img.naturalWidth,
                                                       box: img.getBoundingClientRect().toJSON() }));
  console.log(JSON.stringify({ log, frame, failed: !!failed }));
} finally {
  await browser.close();
}

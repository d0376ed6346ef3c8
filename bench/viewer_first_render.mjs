// assembly.html's size and time to first render in headless Chromium, for finished runs:
//
//   node bench/viewer_first_render.mjs [--loads N] OUT/pawn OUT/elephant ...
//
// Time to first render: from the start of navigation to the first frame of the 3D view (the
// page's performance.now() then), the median of N loads (default 3), each in a fresh browser
// context. Needs the build's npm packages (PAPERCRAFT_VIEWER_MODULES, default
// build/viewer/node_modules) and Chromium (CHROMIUM, default /usr/bin/chromium).

import { existsSync, readFileSync, statSync } from 'node:fs';
import { basename, join, resolve } from 'node:path';
import { launchChromium, openViewer } from '../tests/viewer/harness.mjs';

const args = process.argv.slice(2);
let loads = 3;
if (args[0] === '--loads') {
  loads = Number(args[1]);
  args.splice(0, 2);
}
if (!args.length || !(loads >= 1)) {
  console.error('usage: viewer_first_render.mjs [--loads N] MODEL_DIR...');
  process.exit(2);
}
process.env.PAPERCRAFT_VIEWER_MODULES ||= resolve(new URL('..', import.meta.url).pathname, 'build/viewer/node_modules');

const browser = await launchChromium();
console.log('| model | pieces | pages | assembly.html MB | pages embedded | first render ms (median) |');
console.log('|---|---|---|---|---|---|');
try {
  for (const dir of args) {
    const file = join(dir, 'assembly.html');
    if (!existsSync(file)) throw new Error(`no assembly.html in ${dir}`);
    const pieces = JSON.parse(readFileSync(join(dir, 'pieces.json'), 'utf8'));
    const times = [];
    let embedded = 0;
    for (let i = 0; i < loads; ++i) {
      const { context, page, errors, firstRenderMs } = await openViewer(browser, file);
      if (errors.length) throw new Error(`${file}: ${errors.join('; ')}`);
      embedded = await page.locator('.page img').count();
      times.push(firstRenderMs);
      await context.close();
    }
    times.sort((a, b) => a - b);
    const median = times[Math.floor(times.length / 2)];
    const megabytes = (statSync(file).size / 1e6).toFixed(2);
    console.log(`| ${basename(resolve(dir))} | ${pieces.pieces.length} | ${pieces.pages} | ${megabytes} | ${embedded} of ${pieces.pages} | ${Math.round(median)} |`);
  }
} finally {
  await browser.close();
}

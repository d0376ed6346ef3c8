// Drives assembly.html in Chromium (playwright-core from the viewer's npm packages, Debian's
// chromium): opens a page from file:// with every other request aborted, records console
// errors, and reads the viewer's state (window.viewer). Used by viewer_test.mjs and by
// bench/viewer_first_render.mjs.

import { createRequire } from 'node:module';
import { spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

function required(name) {
  const value = process.env[name];
  if (!value) throw new Error(`${name} is not set (ctest sets it; see tests/CMakeLists.txt)`);
  return value;
}

export function papercraftBinary() {
  const binary = required('PAPERCRAFT');
  if (!existsSync(binary)) throw new Error(`no papercraft binary at ${binary}: build first`);
  return binary;
}

// Runs the papercraft command line; throws with its output when it fails.
export function papercraft(args) {
  const run = spawnSync(papercraftBinary(), args, { encoding: 'utf8', maxBuffer: 1 << 26 });
  if (run.status !== 0)
    throw new Error(`papercraft ${args.join(' ')} exited ${run.status}\n${run.stdout}\n${run.stderr}`);
  return run;
}

// Chromium, started as the tests and benchmarks want it; a browser that cannot start throws.
export async function launchChromium() {
  const modules = required('PAPERCRAFT_VIEWER_MODULES');
  const { chromium } = createRequire(join(modules, 'noop.js'))('playwright-core');
  const executablePath = process.env.CHROMIUM || '/usr/bin/chromium';
  if (!existsSync(executablePath))
    throw new Error(`no Chromium at ${executablePath}: run scripts/install-deps.sh (Debian package chromium)`);
  // WebGL without a GPU: ANGLE on SwiftShader.
  return chromium.launch({
    executablePath,
    args: ['--enable-unsafe-swiftshader', '--use-angle=swiftshader', '--ignore-gpu-blocklist'],
  });
}

// Opens `file` with the network blocked; resolves once the viewer drew its first frame.
export async function openViewer(browser, file, viewport = { width: 1400, height: 900 }) {
  const context = await browser.newContext({ viewport, deviceScaleFactor: 1 });
  const requests = [];
  await context.route('**/*', (route) => {
    const url = route.request().url();
    if (url.startsWith('file:')) return route.continue();
    requests.push(url);
    return route.abort();
  });
  const page = await context.newPage();
  const errors = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  page.on('pageerror', (error) => errors.push(String(error)));
  await page.goto(pathToFileURL(file).href);
  await page.waitForFunction(() => window.viewer && window.viewer.ready, null, { timeout: 120000 });
  const firstRenderMs = await page.evaluate(() => window.viewer.firstRenderMs);
  return { context, page, errors, requests, firstRenderMs };
}

export function state(page) {
  return page.evaluate(() => window.viewer.state());
}

// Share of the element's pixels unlike its background, and how many distinct colours it shows
// (counted on 4 bits per channel), from a screenshot decoded in the page.
export async function screenshotContent(page, selector, background = [0xee, 0xf1, 0xf3]) {
  const png = await page.locator(selector).screenshot();
  return page.evaluate(async ({ base64, background }) => {
    const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
    const bitmap = await createImageBitmap(new Blob([bytes], { type: 'image/png' }));
    const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
    const context = canvas.getContext('2d');
    context.drawImage(bitmap, 0, 0);
    const { data } = context.getImageData(0, 0, bitmap.width, bitmap.height);
    let unlike = 0;
    const colours = new Set();
    for (let i = 0; i < data.length; i += 4) {
      const difference = Math.abs(data[i] - background[0]) + Math.abs(data[i + 1] - background[1]) +
        Math.abs(data[i + 2] - background[2]);
      if (difference > 24) ++unlike;
      colours.add(((data[i] >> 4) << 8) | ((data[i + 1] >> 4) << 4) | (data[i + 2] >> 4));
    }
    return { unlikeShare: unlike / (data.length / 4), colours: colours.size };
  }, { base64: png.toString('base64'), background });
}

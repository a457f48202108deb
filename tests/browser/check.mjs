// Opens an interactive ndfplot page from disk in Debian's Chromium (no server, network off),
// moves its first slider with the mouse and the keyboard, and prints what the page draws before
// and after as JSON on stdout; tests/cli/browser.rs compares the drawn values with `ndfplot eval`.
//
// Usage: node check.mjs <page.html> <screenshot.png>
import { chromium } from "playwright-core";
import { mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { pathToFileURL } from "node:url";

const [page_path, screenshot] = process.argv.slice(2);
if (!page_path || !screenshot) {
  console.error("usage: node check.mjs <page.html> <screenshot.png>");
  process.exit(2);
}

// The flags this machine's Chromium needs (no sandbox as root, no GPU, no background traffic).
const args = [
  "--headless",
  "--no-sandbox",
  "--disable-gpu",
  "--disable-quic",
  "--no-first-run",
  "--disable-background-networking",
  "--disable-component-update",
  "--disable-sync",
];
const profile = mkdtempSync(join(tmpdir(), "ndfplot-chromium-"));
const context = await chromium.launchPersistentContext(profile, {
  executablePath: "/usr/bin/chromium",
  headless: true,
  args,
  viewport: { width: 1100, height: 760 },
  offline: true,
});
try {
  // Any request that is not the page itself (or an inline data: URL) is recorded and refused.
  const external = [];
  await context.route("**/*", (route) => {
    const url = route.request().url();
    if (url.startsWith("file:") || url.startsWith("data:")) return route.continue();
    external.push(url);
    return route.abort();
  });
  const page = context.pages()[0] ?? (await context.newPage());
  const errors = [];
  page.on("pageerror", (e) => errors.push(String(e)));
  page.on("console", (m) => m.type() === "error" && errors.push(m.text()));
  await page.goto(pathToFileURL(resolve(page_path)).href);
  await page.waitForFunction(() => window.ndfplot !== undefined);
  const pixels = () => page.evaluate(() => document.getElementById("plot").toDataURL());
  const before = await page.evaluate(() => window.ndfplot.current());
  const pixelsBefore = await pixels();

  // Click at 70 % of the first slider's track, then one step further with the keyboard.
  const slider = page.locator("#slider-0");
  const box = await slider.boundingBox();
  await page.mouse.click(box.x + 0.7 * box.width, box.y + box.height / 2);
  await slider.press("ArrowRight");
  const after = await page.evaluate(() => window.ndfplot.current());
  const printed = await page.locator("#value-0").textContent();
  const pixelsAfter = await pixels();
  await page.screenshot({ path: screenshot, fullPage: true });

  // The log toggle redraws too.
  await page.locator("#log-y").click();
  const log = await page.evaluate(() => window.ndfplot.current().scale);
  const pixelsLog = await pixels();

  console.log(
    JSON.stringify({
      before,
      after,
      printed,
      log_scale: log,
      canvas_changed: pixelsBefore !== pixelsAfter,
      log_redrawn: pixelsLog !== pixelsAfter,
      external_requests: external,
      errors,
    })
  );
} finally {
  await context.close();
  rmSync(profile, { recursive: true, force: true });
}

// Opens a test page (tests/end_to_end/tiles_cesium.html, tests/end_to_end/tiles_three.html, tests/end_to_end/chain_msft_lod.html,
// clients/chain_three.html, clients/chain_babylon.html) in Debian's Chromium (headless, WebGL on
// SwiftShader) through playwright-core, waits for its result, saves a
// screenshot and prints the result as JSON.
//   node browser_page.mjs PLAYWRIGHT_DIR URL SCREENSHOT.png
import { createRequire } from "node:module";
import path from "node:path";

const [playwrightDir, url, screenshot] = process.argv.slice(2);
const { chromium } = createRequire(path.join(playwrightDir, "index.js"))(playwrightDir);
const browser = await chromium.launch({
    executablePath: "/usr/bin/chromium",
    args: ["--no-sandbox", "--disable-gpu", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-quic",
           "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync"],
});
try {
    const page = await browser.newPage({ viewport: { width: 640, height: 480 } });
    // BOXLOD_PAGE_LOG=1 passes every console message on (the loaders' logs), else only errors.
    page.on("console", (message) => {
        if (message.type() === "error" || process.env.BOXLOD_PAGE_LOG) console.error("page:", message.text());
    });
    await page.goto(url);
    await page.waitForFunction(() => window.result !== undefined, null, { timeout: 150000 });
    const result = await page.evaluate(() => window.result);
    await page.screenshot({ path: screenshot });
    console.log(JSON.stringify(result));
} finally {
    await browser.close();
}

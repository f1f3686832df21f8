// Accessibility check of report.html: axe-core (WCAG 2.1 A and AA rules) in headless Chromium,
// at a desktop width (1400 px) and a phone width (400 px).
//
//   node axe.mjs REPORT_HTML
//
// Prints every violation (rule, impact, help, and for each offending element its selector and
// axe's failure summary) and exits 1 when there is any at either width, 0 when there is none,
// 2 when the check could not run. Run by tests/suite/browser.rs; `npm ci` in this folder
// installs axe-core and playwright-core (the browser is Debian's /usr/bin/chromium, or
// $ORTHOCHECK_CHROMIUM).

import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';

const TAGS = ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'];
const WIDTHS = [1400, 400];
const HEIGHT = 900;

function fail(message) {
  process.stderr.write(`axe.mjs: ${message}\n`);
  process.exit(2);
}

const args = process.argv.slice(2);
if (args.length !== 1) fail('usage: node axe.mjs REPORT_HTML');
const page_url = pathToFileURL(resolve(args[0])).href;
try {
  readFileSync(resolve(args[0]));
} catch (e) {
  fail(`cannot read ${args[0]}: ${e.message}`);
}
const require = createRequire(import.meta.url);
const axe_source = readFileSync(require.resolve('axe-core/axe.min.js'), 'utf8');
const axe_version = require('axe-core/package.json').version;

const browser = await chromium
  .launch({
    executablePath: process.env.ORTHOCHECK_CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: [
      '--headless',
      '--no-sandbox',
      '--disable-gpu',
      // the machine's network is closed: no background connections, no update checks
      '--disable-quic',
      '--no-first-run',
      '--disable-background-networking',
      '--disable-component-update',
      '--disable-sync',
    ],
  })
  .catch((e) => fail(`chromium does not start: ${e.message}`));

/** axe's results on the page in a `width` px wide viewport. */
async function audit(width) {
  const context = await browser.newContext({
    viewport: { width, height: HEIGHT },
    // the page's own policy, if it ever has one, must not keep axe out
    bypassCSP: true,
    reducedMotion: 'reduce',
  });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(page_url, { waitUntil: 'load', timeout: 120_000 });
  await page.addScriptTag({ content: axe_source });
  const results = await page.evaluate(
    (tags) =>
      window.axe.run(document, {
        runOnly: { type: 'tag', values: tags },
        // beside the WCAG tags: every content inside a landmark (axe's best-practice rule)
        rules: { region: { enabled: true } },
        resultTypes: ['violations'],
      }),
    TAGS,
  );
  await context.close();
  return { results, errors };
}

let violations = 0;
try {
  process.stdout.write(`axe-core ${axe_version}, tags ${TAGS.join(' ')}: ${page_url}\n`);
  for (const width of WIDTHS) {
    const { results, errors } = await audit(width);
    for (const e of errors) process.stdout.write(`[${width} px] page error: ${e}\n`);
    const found = [...results.violations].sort((a, b) => (a.id < b.id ? -1 : a.id > b.id ? 1 : 0));
    const nodes = found.reduce((n, v) => n + v.nodes.length, 0);
    process.stdout.write(
      `\n[${width}x${HEIGHT}] ${found.length} violation(s) on ${nodes} element(s)\n`,
    );
    for (const v of found) {
      process.stdout.write(`\n${v.id} (${v.impact}): ${v.help}\n  ${v.helpUrl}\n`);
      for (const node of v.nodes) {
        process.stdout.write(`  - ${node.target.map((t) => JSON.stringify(t)).join(' >> ')}\n`);
        for (const line of (node.failureSummary || '').split('\n')) {
          if (line.trim()) process.stdout.write(`      ${line.trim()}\n`);
        }
      }
    }
    violations += nodes;
  }
} catch (e) {
  await browser.close();
  fail(e.stack || String(e));
}
await browser.close();
process.stdout.write(
  violations === 0
    ? '\naxe: no violation at either width\n'
    : `\naxe: ${violations} violating element(s) in all\n`,
);
process.exit(violations === 0 ? 0 : 1);

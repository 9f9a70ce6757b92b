// Renders an exported .glb in three.js inside headless Debian chromium and saves the picture.
// Usage: node tools/web/shoot.mjs MODEL.glb OUT.png [--width W] [--height H] [--mode albedo|lit]
//        [--bg r,g,b] [--mpu metres-per-unit]
// A local HTTP server (127.0.0.1, a free port) serves tools/web and the model; the page posts its
// canvas back as a PNG, so the picture is taken when three.js has drawn, not after a guessed wait.
import { createServer } from 'node:http';
import { spawn } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
const opt = (name, def) => { const i = args.indexOf(name); return i >= 0 ? args[i + 1] : def; };
const [model, out] = args;
if (!model || !out) { console.error('usage: node shoot.mjs MODEL.glb OUT.png [--width W --height H --mode albedo|lit]'); process.exit(2); }
const width = opt('--width', '400'), height = opt('--height', '400');
const types = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.glb': 'model/gltf-binary' };

let browser;
const finish = (code, message) => {
  if (message) console.error(message);
  if (browser) {
    browser.removeAllListeners('exit');
    try { process.kill(-browser.pid, 'SIGKILL'); } catch { /* already gone */ }
  }
  process.exit(code);
};
const server = createServer((req, res) => {
  const url = new URL(req.url, 'http://localhost');
  if (req.method === 'POST' && url.pathname === '/result') {
    let body = '';
    req.on('data', (c) => { body += c; });
    req.on('end', () => {
      res.end('ok');
      if (!body.startsWith('data:image/png;base64,')) finish(1, 'three.js page: ' + body);
      writeFileSync(out, Buffer.from(body.slice('data:image/png;base64,'.length), 'base64'));
      finish(0);
    });
    return;
  }
  const file = url.pathname === '/model.glb' ? path.resolve(model) : path.join(here, path.normalize(url.pathname));
  try {
    const data = readFileSync(file);
    res.writeHead(200, { 'Content-Type': types[path.extname(file)] || 'application/octet-stream' });
    res.end(data);
  } catch {
    res.writeHead(404);
    res.end();
  }
});
server.listen(0, '127.0.0.1', () => {
  const port = server.address().port;
  const page = `http://127.0.0.1:${port}/compare.html?model=/model.glb&w=${width}&h=${height}` +
               `&mode=${opt('--mode', 'albedo')}&bg=${opt('--bg', '0,0,0')}&mpu=${opt('--mpu', '0.1')}`;
  const profile = mkdtempSync(path.join(tmpdir(), 'marble-chromium-'));
  process.on('exit', () => {
    try { rmSync(profile, { recursive: true, force: true, maxRetries: 5 }); } catch { /* chromium's last writes */ }
  });
  browser = spawn(process.env.CHROMIUM || 'chromium', [
    '--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
    '--disable-sync', '--no-first-run', `--user-data-dir=${profile}`,
    // WebGL without a GPU: ANGLE on SwiftShader (software), which chromium asks to opt into.
    '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
    `--window-size=${width},${height}`, page,
  ], { stdio: ['ignore', 'ignore', 'pipe'], detached: true });  // its own process group: killed whole
  let log = '';
  browser.stderr.on('data', (d) => { log += d; });
  browser.on('exit', (code) => finish(1, `chromium exited (${code}) before the page answered:\n${log.slice(-2000)}`));
  setTimeout(() => finish(1, 'timed out waiting for the three.js page\n' + log.slice(-2000)), 90000);
});

// A connection flood from a thread of its own (tests/serve/attacks.mjs,
// connectionFlood): an attacker is another program, so the operator's
// requests in the test's main thread do not wait behind the flood's work.
// workerData: {port, ms, oneByte}; posts the number of connections opened.
import net from "node:net";
import { parentPort, workerData } from "node:worker_threads";

const { port, ms, oneByte } = workerData;
const request = `GET /api/v1/state HTTP/1.1\r\nHost: 127.0.0.1:${port}\r\n\r\n`;
const held = [];
let opened = 0, stop = false;

// Each opener: a new connection as soon as the last one is up; a third
// closed at once, a third sending a request without the token, a third
// silent (oneByte: each sends the first byte of a request, then nothing).
async function opener() {
  while (!stop) {
    const x = net.connect(port, "127.0.0.1");
    x.on("error", () => {});
    x.on("data", () => {});
    ++opened;
    await new Promise((done) => { x.on("connect", done); x.on("error", done); x.on("close", done); });
    const kind = opened % 3;
    if (oneByte) {
      x.write("G");
      held.push(x);
    } else if (kind === 0) x.destroy();
    else {
      if (kind === 1) x.write(request);
      held.push(x);
    }
    if (held.length > 1500) held.shift().destroy();  // the test's own file descriptors
  }
}

setTimeout(() => { stop = true; }, ms);
await Promise.all(Array.from({ length: 16 }, opener));
held.forEach((x) => x.destroy());
parentPort.postMessage(opened);

// Starts `nck serve` for a browser test and reads the URL it prints; stops
// it at the end. --max-wall bounds its life should the test die first.
import { spawn } from "node:child_process";

export function startServer(nck, cwd, args, maxWallS = 170) {
  const child = spawn(nck, ["serve", ...args, "--port", "0", "--max-wall", String(maxWallS)],
    { cwd, stdio: ["ignore", "pipe", "pipe"] });
  let stderr = "";
  child.stderr.on("data", (d) => { stderr += d; });
  const url = new Promise((resolve, reject) => {
    let out = "";
    const timer = setTimeout(() => reject(new Error("nck serve printed no URL within 10 s: " + stderr)), 10000);
    child.stdout.on("data", (d) => {
      out += d;
      const m = /nck serve: (http:\/\/127\.0\.0\.1:\d+\/\?token=\S+)/.exec(out);
      if (m) { clearTimeout(timer); resolve(m[1]); }
    });
    child.on("exit", (code) => { clearTimeout(timer); reject(new Error(`nck serve exited ${code}: ${stderr}`)); });
  });
  const stop = () => new Promise((resolve) => {
    if (child.exitCode !== null) return resolve(child.exitCode);
    child.on("exit", (code, signal) => resolve(code ?? signal));
    child.kill("SIGTERM");
  });
  return { url, stop, stderr: () => stderr };
}

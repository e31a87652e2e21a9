// Flubber (npm "flubber", the web's usual shape morph) on the benchmark's outlines: run by method_crossings.py
// with NODE_PATH pointing at a folder holding flubber (npm install flubber there); never at test time.
// stdin: [{"a": [[x, y]...], "b": [[x, y]...], "t": [..], "segment": s}...]; stdout: per case, per t, a ring
const flubber = require("flubber");
let input = "";
process.stdin.on("data", (d) => (input += d));
process.stdin.on("end", () => {
  const out = JSON.parse(input).map((c) => {
    const f = flubber.interpolate(c.a, c.b, { string: false, maxSegmentLength: c.segment });
    const start = process.hrtime.bigint();
    const rings = c.t.map((t) => f(t));
    const ns = Number(process.hrtime.bigint() - start);
    return { rings, ms: ns / 1e6 / c.t.length };
  });
  process.stdout.write(JSON.stringify(out));
});

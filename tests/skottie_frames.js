// Skottie (CanvasKit, CPU raster) draws a Lottie file's frames: node skottie_frames.js CANVASKIT_DIR IN.json W H OUT.rgba F1 F2 ...
const fs = require("fs");
const path = require("path");
const [dir, input, width, height, output, ...frames] = process.argv.slice(2);
const init = require(path.join(dir, "bin", "full", "canvaskit.js"));
init({ locateFile: (file) => path.join(dir, "bin", "full", file) }).then((CK) => {
  const w = Number(width), h = Number(height);
  const animation = CK.MakeAnimation(fs.readFileSync(input, "utf8"));
  if (!animation) { console.error("Skottie could not read " + input); process.exit(3); }
  const surface = CK.MakeSurface(w, h);
  const canvas = surface.getCanvas();
  const chunks = [];
  for (const f of frames) {
    canvas.clear(CK.TRANSPARENT);
    animation.seekFrame(Number(f));
    animation.render(canvas, CK.LTRBRect(0, 0, w, h));
    surface.flush();
    const pixels = canvas.readPixels(0, 0, { width: w, height: h, colorType: CK.ColorType.RGBA_8888,
      alphaType: CK.AlphaType.Unpremul, colorSpace: CK.ColorSpace.SRGB });
    chunks.push(Buffer.from(pixels.buffer, pixels.byteOffset, pixels.byteLength));
  }
  fs.writeFileSync(output, Buffer.concat(chunks));
});

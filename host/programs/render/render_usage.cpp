// pfx-render --help, in the order a user reads it: what to run it on, which effects, what comes
// out, sequences. Each section is a function of its own so that each stays short to read.
#include "render_options.hpp"

namespace pfx::app {

namespace {

// The forms of the command line and what the program does.
const char* usage_synopsis() {
  return
      "usage: pfx-render [--plugins DIR]... (--demo [--lights N] [--seed S] | --demo-image\n"
      "                  | --scene FILE.obj [--lights N] [--seed S]\n"
      "                  | --input IMG.exr [--layer NAME] [--depth DEPTH.exr]\n"
      "                  | --input IMG.png [--transfer srgb|linear]) [--size WxH]\n"
      "                  [--camera fovy=45,near=0.1,far=1000] [--chain a,b,...]\n"
      "                  [--preset FILE [--strict]] [--set effect.param=value]...\n"
      "                  --out FILE.exr|FILE.png... [--json]\n"
      "       pfx-render --input SHOT.%04d.exr [--depth Z.%04d.exr] --frames FIRST-LAST[xSTEP]\n"
      "                  [--chunk N [--chunk-index I]] [--overwrite] [--report R.%04d.json]\n"
      "                  [--print-frames] [effects] --out OUT.%04d.exr|.png... [--json]\n"
      "       pfx-render --list [--json] [--plugins DIR]...\n"
      "\n"
      "Runs a chain of pfx effects over one frame or a sequence, headless (EGL, no window), and writes the result.\n"
      "\n";
}

// What the chain runs over: a scene, a procedural image or an image file.
const char* usage_input() {
  return
      "input\n"
      "  --demo               the built-in 3D scene, made in code: a floor, boxes and spheres, emissive\n"
      "                       objects and 400 point lights on a 20x20 grid; the host renders its\n"
      "                       G-buffer, so effects get colour (emissive + ambient), linear depth,\n"
      "                       normal, albedo, emissive and the lights; --size WxH (default 1280x720)\n"
      "  --lights N           with --demo: N more lights at random inside the scene (default 0)\n"
      "  --seed S             with --demo: the seed of every random choice (default 1)\n"
      "  --scene FILE.obj     a model imported through the importer plugins (pfx-import reads the\n"
      "                       same), rendered like --demo: its materials (Kd, Ke, map_Kd, map_Ke;\n"
      "                       PNG, JPEG, TGA or BMP), a light rig scaled to the model (key light,\n"
      "                       sky, 400 point lights around it: --lights N for N), a camera framing\n"
      "                       the model's bounds (docs/scenes.md); --size WxH (default 1280x720)\n"
      "  --demo-image         the procedural HDR image (bright spots, fine detail, a depth ramp):\n"
      "                       colour and depth only, no lights\n"
      "  --input IMG.exr      an OpenEXR image (half, float or uint; scanline, tiled or multi-part):\n"
      "                       R, G, B (a missing one is 0) and A (else 1); or Y as grey (Y, RY, BY\n"
      "                       converted to RGB); or its only channel as grey. Colour in a layer\n"
      "                       (diffuse.R, ...) when the file has no plain one: the only such layer.\n"
      "                       A Z channel is linear depth (m). --json or the log says what was read\n"
      "  --layer NAME         with --input: read the part or layer NAME (e.g. diffuse for diffuse.R)\n"
      "  --depth DEPTH.exr    linear depth (m) from another EXR: its Z channel, else a 'depth' channel\n"
      "                       or the Z of a layer, else R, else Y, else its only channel\n"
      "  --input IMG.png      an 8-bit PNG (RGB, RGBA or grey; 16-bit is reduced to 8): a display-\n"
      "                       referred frame, as a video tool hands to the frei0r plugins and the\n"
      "                       GStreamer element (docs/hosts.md). It is decoded to linear light on the\n"
      "                       GPU by the same code as those hosts (--transfer), its PNG outputs are\n"
      "                       encoded back the same way (not tone-mapped: --exposure and --tone do\n"
      "                       not apply), so pfx-render gives the bytes they give; alpha is kept as\n"
      "                       it was. Parameters start from their display-referred defaults\n"
      "                       (--defaults)\n"
      "  --transfer T         with an 8-bit --input: srgb (default: the exact sRGB curve, what almost\n"
      "                       every video and picture holds) or linear (the codes are linear light)\n"
      "  --max-input-pixels N refuse an input EXR whose header declares more than N pixels, before\n"
      "                       reading or allocating anything (default 67108864 = 8192 x 8192)\n"
      "  --camera K=V,...     the camera the effects see: fovy (degrees, default 45), near (m, 0.1),\n"
      "                       far (m, 1000, or inf); for an image the camera sits at the origin\n"
      "                       looking down -Z; for --demo the keys given replace the scene camera's\n"
      "                       (it keeps its place and its other settings)\n"
      "\n";
}

// Which effects run, and with which values.
const char* usage_effects() {
  return
      "effects\n"
      "  --plugins DIR        load plugins from DIR (repeatable); default: the plugins folder next to\n"
      "                       this program's folder; PFX_PLUGIN_PATH (':'-separated) adds more\n"
      "  --chain a,b,...      the effects to run, in order (default: every loaded effect, lighting\n"
      "                       first, then depth of field, then bloom and glare, then the rest); an\n"
      "                       effect may appear more than once, each instance with its own values;\n"
      "                       none (or an empty list): no effect\n"
      "  --set E.P=V          set parameter P of effect E (repeatable); see --list for every parameter.\n"
      "                       E#N is the N-th instance of E in the chain (--chain bloom,glare,bloom:\n"
      "                       bloom#2.strength=0.3 sets the second bloom); plain E is E#1\n"
      "  --preset FILE        a preset: pfx-view's JSON (docs/viewer.md), with the chain, each effect\n"
      "                       on or off, parameter values, the camera and the display settings, or\n"
      "                       ReShade's .ini (docs/fx.md); --chain, --set, --camera, --exposure and\n"
      "                       --tone given as well override it. What it names that is not loaded or\n"
      "                       does not fit is left out, named in one warning\n"
      "  --strict             refuse instead (exit 3) a preset that does not apply whole: for farm\n"
      "                       jobs, where a frame without part of its look is a wasted frame\n"
      "  --defaults D         the defaults parameters start from before --preset and --set: scene\n"
      "                       (scene-linear HDR, where 1 is diffuse white and highlights go far\n"
      "                       above) or display (display-referred frames holding nothing above 1,\n"
      "                       e.g. bloom's threshold 0.6 instead of 1; --list shows both). Default:\n"
      "                       display for an 8-bit --input, scene otherwise; give display for an\n"
      "                       EXR made from an 8-bit source\n"
      "  --list               list plugins, effects and parameters (with --json: all metadata)\n"
      "\n";
}

// The files and the report written.
const char* usage_output() {
  return
      "output\n"
      "  --out FILE           .exr (half; --float for 32-bit) or .png (tone-mapped, sRGB; from an\n"
      "                       8-bit --input: encoded back as --transfer says, with the input's alpha);\n"
      "                       repeatable; every file is written to a temporary name, then renamed\n"
      "  --float              32-bit float EXR output\n"
      "  --exposure EV        exposure for PNG output (default 0)\n"
      "  --tone NAME          tone curve for PNG output: linear (default), reinhard, aces\n"
      "  --json               print one JSON object to stdout: renderer, effects, per-pass times,\n"
      "                       total_ms, peak_target_bytes, output statistics, effect reports\n"
      "                       (a second instance of an effect is named E#2, and so on)\n"
      "  --timing MODE        auto (default: finish on a software renderer, gpu elsewhere), gpu\n"
      "                       (GL timestamp queries, waited for once the frame is rendered),\n"
      "                       finish (glFinish + CPU clock around each pass: what llvmpipe\n"
      "                       really spends), off\n"
      "  -v, --verbose        also print debug messages\n"
      "\n";
}

// Frame ranges, resuming and job arrays, and the exit codes.
const char* usage_sequences() {
  return
      "sequences (docs/farm.md)\n"
      "  --frames A-B[xS]     render frames A to B (every S-th) in one process, plugins and GL objects\n"
      "                       kept between frames; --input, every --out and --report are then file\n"
      "                       name patterns: shot.%04d.exr, shot.####.exr or shot.@@@@.exr (each # or\n"
      "                       @ one digit; %d or a lone @: no padding); --depth a pattern or one file.\n"
      "                       Effects see frame N as frame index N, at N / 24 seconds\n"
      "  --overwrite          render every frame; without it a frame whose outputs all exist is skipped\n"
      "                       (outputs are written under a temporary name and renamed when complete,\n"
      "                       so one that exists is whole): a rerun finishes what an interrupted run left\n"
      "  --report PATTERN     also write each frame's JSON report (status, error, times) to its own file\n"
      "                       (only for frames rendered or failed: a skipped frame keeps its report)\n"
      "  --chunk N            the range in chunks of N frames, in order (the last may be shorter)\n"
      "  --chunk-index I      render only chunk I of them, from 0: one task of a job array (pfx-farm)\n"
      "  --print-frames       print the frame plan as one JSON object and render nothing: each frame's\n"
      "                       input, depth, outputs and report file, its chunk (with --chunk), and\n"
      "                       whether it is done; needs no GL (what pfx-farm reads)\n"
      "  A progress line (frame, time per frame, time left) goes to a terminal, a\n"
      "  line per frame to anything else; --json prints one JSON line per frame and a last one with the\n"
      "  summary. SIGINT or SIGTERM stops after the frame being written. A missing or damaged input\n"
      "  fails that frame only.\n"
      "\n"
      "exit codes: 0 ok, 1 internal error (e.g. no OpenGL 4.5 context), 2 usage, 3 bad input file,\n"
      "            4 plugin or effect error, 5 some frames of a sequence failed (the others were\n"
      "            written), 130 or 143 stopped by SIGINT or SIGTERM (rerun to finish)\n";
}

}  // namespace

std::string render_usage() {
  return std::string(usage_synopsis()) + usage_input() + usage_effects() + usage_output() + usage_sequences();
}

}  // namespace pfx::app

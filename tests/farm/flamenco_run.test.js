// Runs compiled Soak Flamenco jobs for real on this machine, as Workers
// would: each task's commands after the Manager's variable replacement, in an
// order that respects the dependencies. Checks
//  1. soak-bake (drying, turbulence): every chunked frame equals the frame of
//     one soak run over the whole range, pixel for pixel (idiff, no tolerance);
//  2. soak-drying-animation (the add-on's Image wetness source), its render
//     tasks in Blender 3.4, 4.3 and 5.2 (the Debian 13 and sid roots of
//     tests/blender/run_blender.sh, SOAK_BLENDER43_ROOT, SOAK_BLENDER52_ROOT): the baked maps equal
//     one soak run's; every frame is rendered; where the map of a frame is dry
//     the render equals the all-dry last frame's, where it is wet the render
//     is darker, and the frames brighten as the map's mean wetness falls (wet
//     materials are darker: [JLD99]). The blend file is made in 3.4 and
//     opened by 4.3 and 5.2, as a farm's newer Workers would.
// Usage: node flamenco_run.test.js REPO_ROOT SOAK_BINARY TMP_DIR
"use strict";
const assert = require("node:assert/strict");
const fs = require("node:fs");
const path = require("node:path");
const {spawnSync} = require("node:child_process");
const F = require("./flamenco_standin.js");

const [root, soak, tmpArg] = process.argv.slice(2);
const tmp = path.resolve(tmpArg);
fs.rmSync(tmp, {recursive: true, force: true});
fs.mkdirSync(tmp, {recursive: true});
const scripts = path.join(root, "farm/flamenco/scripts");
const t0 = Date.now();
const secs = () => ((Date.now() - t0) / 1000).toFixed(1);

function run(argv, env) {
    const r = spawnSync(argv[0], argv.slice(1), {encoding: "utf8", env: Object.assign({}, process.env, env || {})});
    if (r.error) throw new Error(`${argv[0]}: ${r.error.message}`);
    return r;
}
function mustRun(argv, env) {
    const r = run(argv, env);
    if (r.status !== 0) {
        throw new Error(`exit ${r.status}: ${argv.join(" ").slice(0, 400)}\n${(r.stdout + r.stderr).slice(-2000)}`);
    }
    return r;
}

// Every task of a compiled job, commands expanded for a Linux worker.
function runJob(compiled, variables) {
    let n = 0;
    for (const task of F.dependencyOrder(compiled.tasks)) {
        for (const cmd of F.expandTask(task, variables).commands) {
            const argv = F.commandArgv(cmd);
            if (argv === null) F.runMakeDirectory(cmd);
            else mustRun(argv, {BLENDER_USER_SCRIPTS: path.join(tmp, "user_scripts")});
            n++;
        }
    }
    return n;
}

function framePath(pattern, f) {
    return pattern.replace("%04d", String(f).padStart(4, "0"));
}

// Pixels of several images from one oiiotool --dumpdata run (OIIO starts
// slowly): file -> {width, height, channels, text: [per-pixel value strings],
// data: Float64Array}. Printed with 9 decimals, which tells apart any two
// half floats in [0, 1] (their spacing is at least 6e-8).
function readImages(files) {
    const r = run(["oiiotool", "--dumpdata"].concat(files));
    assert.equal(r.status, 0, r.stderr);
    const out = new Map();
    let cur = null;
    for (const line of r.stdout.split("\n")) {
        const head = /^(.*\S)\s+:\s+(\d+)\s+x\s+(\d+), (\d+) channel/.exec(line);
        if (head) {
            cur = {width: +head[2], height: +head[3], channels: +head[4], text: [], values: []};
            out.set(head[1], cur);
            continue;
        }
        const px = /^\s+Pixel \((\d+), (\d+)\): (.*)$/.exec(line);
        if (px && cur) {
            // integer formats: "raw values (normalised values)"
            const norm = /\(([^)]*)\)/.exec(px[3]);
            const text = (norm ? norm[1] : px[3]).trim();
            cur.text.push(text);
            for (const v of text.split(/\s+/)) cur.values.push(Number(v));
        }
    }
    for (const f of files) {
        const img = out.get(f);
        assert.ok(img, `oiiotool printed no pixels of ${f}`);
        assert.equal(img.text.length, img.width * img.height, `${f}: pixel count`);
        img.data = Float64Array.from(img.values);
    }
    return out;
}

// Pixel-for-pixel equality of two dumped images (no tolerance).
function assertSameImage(images, a, b) {
    const x = images.get(a), y = images.get(b);
    assert.deepEqual([x.width, x.height, x.channels], [y.width, y.height, y.channels], `${a} vs ${b}: size`);
    const bad = x.text.findIndex((v, i) => v !== y.text[i]);
    assert.equal(bad, -1, `${a} and ${b} differ first at pixel ${bad}: ${x.text[bad]} vs ${y.text[bad]}`);
}
function imagesDiffer(images, a, b) {
    return images.get(a).text.join("|") !== images.get(b).text.join("|");
}

function luminance(img) {
    const out = new Float64Array(img.width * img.height);
    for (let p = 0; p < out.length; p++) {
        let s = 0;
        for (let c = 0; c < img.channels; c++) s += img.data[p * img.channels + c];
        out[p] = s / img.channels;
    }
    return out;
}
const mean = (a) => a.reduce((s, x) => s + x, 0) / a.length;

let failures = 0;
function check(name, fn) {
    try {
        fn();
        console.log(`ok   ${name} (${secs()} s)`);
    } catch (e) {
        failures++;
        console.log(`FAIL ${name}\n     ${String(e && e.stack || e).split("\n").slice(0, 12).join("\n     ")}`);
    }
}

// ---- 1. soak-bake in chunks vs one run ----
const bake = F.loadJobType(path.join(scripts, "soak_bake.js"));
// A mask whose texel k (1..10) is k texels from the one dry texel: it starts
// drying at time k/10, and --t-fill 1e-20 (far below one ulp) makes that a
// step, dry iff t > k/10. At time 0 and frame time 0.03, frame 11 is at
// 10 * 0.03 = 0.3 = texel 3's time (wet), but a chunk 10-12 started at its
// own time 0.27 would give it 0.27 + 0.03, one ulp above (dry;
// tests/cli/bake.sh shows it): the comparison sees a last-bit time error.
const stepMask = path.join(tmp, "step_mask.pgm");
fs.writeFileSync(stepMask, "P2\n11 1\n1\n0 1 1 1 1 1 1 1 1 1 1\n");
// A wall leaning 60 degrees from the horizontal (z up), UVs across it: in rain
// its film rises and runs over time, so frames differ (tests/c/bake/test_bake_rain_frames.c
// checks the physics; here only that chunks equal one run).
const wallMesh = path.join(tmp, "wall.obj");
fs.mkdirSync(tmp, {recursive: true});
fs.writeFileSync(wallMesh, "v 0 0 0\nv 1 0 0\nv 1 0.5 0.866\nv 0 0.5 0.866\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n" +
                 "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
const bakeCases = [
    {kind: "rain-frames", soak_kind: "rain", frames: "0-4", chunk_size: 2, input: wallMesh, width: 24, height: 24,
     seed: 1, time: 0, frame_time: 0.5, extra_args: "--up z --rays 4 --duration 1.5 --steps 6 --rainfall 50"},
    {kind: "drying", frames: "1-12", chunk_size: 3, input: stepMask, seed: 3, time: 0, frame_time: 0.03,
     extra_args: "--t-fill 1e-20"},
    {kind: "turbulence", frames: "0-3", chunk_size: 2, width: 40, height: 32, seed: 9, time: 0,
     frame_time: 1 / 24, extra_args: "--evolve 1.5 --octaves 3"},
];
for (const c of bakeCases) {
    check(`soak-bake ${c.kind} ${c.frames} in chunks of ${c.chunk_size} == one soak run`, () => {
        const dir = path.join(tmp, `bake_${c.kind}`);
        const settings = Object.assign(F.defaults(bake.jobType), c, {output_dir: path.join(dir, "chunked")});
        const compiled = bake.compile(settings);
        const execs = (t) => t.commands.filter((x) => x.name === "exec").length;
        assert.ok(compiled.tasks.every((t) => execs(t) === 1), "a chunk is not exactly one soak run");
        const n = runJob(compiled, {soak});
        const [A, B] = c.frames.split("-").map(Number);
        const single = path.join(dir, "single", "wet.%04d.exr");
        fs.mkdirSync(path.dirname(single), {recursive: true});
        const dims = ["--width", String(c.width), "--height", String(c.height)];
        const size = c.kind === "drying" ? [c.input] : c.input ? [c.input].concat(dims) : dims;
        mustRun([soak, "bake", c.soak_kind || c.kind].concat(size, ["--seed", String(c.seed)], F.shellSplit(c.extra_args),
                ["--frames", c.frames, "--time", String(c.time), "--frame-time", String(c.frame_time), "-o", single]));
        const pairs = [];
        for (let f = A; f <= B; f++) pairs.push([framePath(path.join(dir, "chunked", "wet.%04d.exr"), f), framePath(single, f)]);
        const images = readImages([].concat(...pairs));
        for (const [x, y] of pairs) assertSameImage(images, x, y);
        if (c.kind === "drying") {
            // The case's point: texel 3 starts drying exactly at frame 11's time (0.3), a step.
            const texel3 = (f) => images.get(framePath(single, f)).data[3];
            assert.deepEqual([texel3(11), texel3(12)], [1, 0], "texel 3 should be wet at frame 11, dry at 12");
        }
        assert.ok(imagesDiffer(images, framePath(single, A), framePath(single, B)), "first and last frames are " +
                  "equal: the sequence does not change, the comparison proves little");
        console.log(`     ${compiled.tasks.length} tasks, ${n} commands (${compiled.tasks.map(execs).join("+")} soak runs), ` +
                    `${B - A + 1} frames identical`);
    });
}

// ---- 2. soak-drying-animation: bake, then Blender renders ----
const size = 32;
const anim = F.loadJobType(path.join(scripts, "soak_drying_animation.js"));
const animDir = path.join(tmp, "anim");
const blend = path.join(animDir, "shot.blend");
check("soak-drying-animation: the shot's blend file (Blender 3.4, the add-on's Image source)", () => {
    fs.mkdirSync(path.join(tmp, "user_scripts"), {recursive: true});
    const zip = path.join(animDir, "soak_blender.zip");
    fs.mkdirSync(animDir, {recursive: true});
    mustRun(["/usr/bin/python3", path.join(root, "blender_addon/build_zip.py"), zip]);
    mustRun(["blender", "-b", "--factory-startup", "--python-exit-code", "1", "--python",
             path.join(root, "tests/farm/make_blend.py"), "--", "--addon", zip, "--out", blend, "--size", String(size)],
            {BLENDER_USER_SCRIPTS: path.join(tmp, "user_scripts")});
    console.log(`     blend file made (${secs()} s)`);
});

// Blender 4.3 and 5.2 as a Worker's {blender}: wrappers around run_blender.sh's
// raw mode (Blender's own arguments, inside the Debian 13 / sid root).
const wrappers = {};
for (const version of ["4.3", "5.2"]) {
    wrappers[version] = path.join(tmp, "blender" + version.replace(".", ""));
    fs.writeFileSync(wrappers[version], `#!/bin/sh\nSOAK_BLENDER=${version} SOAK_BLENDER_RAW=1 exec bash ` +
                     JSON.stringify(path.join(root, "tests/blender/run_blender.sh")) + ' "$@"\n', {mode: 0o755});
}

for (const [version, blenderExe] of [["3.4", "blender"], ["4.3", wrappers["4.3"]], ["5.2", wrappers["5.2"]]]) {
    check(`soak-drying-animation 1-4, Blender ${version}: maps equal one run, renders follow the drying`, () => {
        const dir = path.join(animDir, version);
        fs.mkdirSync(dir, {recursive: true});
        const settings = Object.assign(F.defaults(anim.jobType), {
            frames: "1-4", chunk_size: 2, bake_chunk_size: 3, width: size, height: size, seed: 2, noise: 1,
            t_fill: 0.25, time: 0, frame_time: 1 / 3, render_output_root: path.join(dir, "render"),
            render_output_path: path.join(dir, "render", "shot", "{timestamp}", "######"),
            blendfile: blend, format: "PNG", scene: "Scene"});
        const compiled = anim.compile(settings);
        const renderDir = path.dirname(compiled.settings.render_output_path);
        // blenderArgs: Flamenco's default "-b -y" plus --factory-startup, so the
        // test sees no user preferences.
        const n = runJob(compiled, {soak, blender: blenderExe, blenderArgs: "-b -y --factory-startup"});
        console.log(`     ${compiled.tasks.length} tasks, ${n} commands run (${secs()} s)`);

        const wet = path.join(renderDir, "wetmap", "wet.%04d.exr");
        const single = path.join(dir, "single", "wet.%04d.exr");
        fs.mkdirSync(path.dirname(single), {recursive: true});
        mustRun([soak, "bake", "drying", "--width", String(size), "--height", String(size), "--seed", "2",
                 "--t-fill", "0.25", "--noise", "1", "--frames", "1-4", "--time", "0", "--frame-time", String(1 / 3),
                 "-o", single]);
        const pngs = [1, 2, 3, 4].map((f) => path.join(renderDir, `${String(f).padStart(6, "0")}.png`));
        for (const png of pngs) assert.ok(fs.existsSync(png), `render missing: ${png}`);
        const files = [1, 2, 3, 4].map((f) => [framePath(wet, f), framePath(single, f)]);
        const images = readImages([].concat(...files, pngs));
        const maps = [], renders = [];
        for (let f = 1; f <= 4; f++) {
            assertSameImage(images, files[f - 1][0], files[f - 1][1]);
            const img = images.get(pngs[f - 1]);
            assert.deepEqual([img.width, img.height], [size, size], "render size");
            renders.push(luminance(img));
            maps.push(images.get(framePath(wet, f)).data);
        }
        // Frame 4 is at drying time 1: the schedule says all dry.
        assert.equal(Math.max(...maps[3]), 0, "frame 4 (time 1) should be dry everywhere");
        const dry = renders[3];
        const mapMeans = maps.map(mean), renderMeans = renders.map(mean);
        console.log(`     mean wetness ${mapMeans.map((x) => x.toFixed(3)).join(" ")}; ` +
                    `mean render ${renderMeans.map((x) => x.toFixed(4)).join(" ")}`);
        for (let f = 1; f < 4; f++) {
            assert.ok(mapMeans[f] < mapMeans[f - 1], `wetness does not fall from frame ${f} to ${f + 1}`);
            assert.ok(renderMeans[f] > renderMeans[f - 1], `render does not brighten from frame ${f} to ${f + 1}`);
        }
        // Per pixel (one texel per pixel): dry texels render as the dry frame,
        // wet ones (w >= 0.5) darker by more than the 16-bit quantum and noise.
        let dryPx = 0, wetPx = 0, worstDry = 0, leastDarkening = Infinity;
        for (let f = 0; f < 3; f++) {
            for (let p = 0; p < dry.length; p++) {
                if (maps[f][p] === 0) {
                    dryPx++;
                    worstDry = Math.max(worstDry, Math.abs(renders[f][p] - dry[p]));
                } else if (maps[f][p] >= 0.5) {
                    wetPx++;
                    leastDarkening = Math.min(leastDarkening, dry[p] - renders[f][p]);
                }
            }
        }
        console.log(`     ${dryPx} dry pixels: worst |render - dry render| ${worstDry.toExponential(2)}; ` +
                    `${wetPx} wet pixels: least darkening ${leastDarkening.toFixed(4)}`);
        assert.ok(dryPx > 50 && wetPx > 50, "too few dry or wet pixels for the per-pixel check");
        // Same shading inputs, same Cycles seed: the same pixel, up to one 16-bit step.
        assert.ok(worstDry <= 1 / 65535, "a dry texel renders differently from the dry frame");
        assert.ok(leastDarkening > 0.01, "a wet texel does not render darker than dry");
    });
}

check("soak-drying-animation: a render task fails when no material has the Image source", () => {
    const dir = animDir;
    const settings = Object.assign(F.defaults(anim.jobType), {
        frames: "1", render_output_root: path.join(dir, "render2"), material: "NoSuchMaterial",
        render_output_path: path.join(dir, "render2", "######"), blendfile: blend,
        format: "PNG", scene: "Scene"});
    const render = anim.compile(settings).tasks.find((t) => t.type === "blender");
    const cmd = F.expandTask(render, {blender: "blender", blenderArgs: "-b -y --factory-startup"}).commands[0];
    const r = run(F.commandArgv(cmd));
    assert.notEqual(r.status, 0, "Blender rendered without a wet-map source");
    assert.match(r.stdout + r.stderr, /Soak: no material 'NoSuchMaterial' has a Soak Image wetness source/);
    assert.ok(!fs.existsSync(path.join(dir, "render2", "000001.png")), "a frame was rendered anyway");
});

console.log(`${failures ? "FAILED" : "passed"} in ${secs()} s`);
process.exit(failures ? 1 : 0);

// Compiles jobs of the Soak Flamenco job types in the Manager stand-in
// (flamenco_standin.js) and checks tasks, chunks, dependencies and command
// lines against values worked out here from Flamenco's chunking rules and
// soak's frame-time formula; checks the scripts against goja's limits and
// that the checked-in scripts are what farm/flamenco/build_scripts.sh writes.
// Usage: node flamenco_compile.test.js REPO_ROOT TMP_DIR
"use strict";
const assert = require("node:assert/strict");
const fs = require("node:fs");
const path = require("node:path");
const {execFileSync} = require("node:child_process");
const F = require("./flamenco_standin.js");

const root = process.argv[2], tmp = process.argv[3];
const scripts = path.join(root, "farm/flamenco/scripts");
let failures = 0, checks = 0;
function check(name, fn) {
    checks++;
    try {
        fn();
        console.log(`ok   ${name}`);
    } catch (e) {
        failures++;
        console.log(`FAIL ${name}\n     ${String(e && e.stack || e).split("\n").slice(0, 6).join("\n     ")}`);
    }
}
function throwsWith(fn, pattern) {
    let msg = null;
    try { fn(); } catch (e) { msg = String(e); }
    assert.ok(msg !== null, `expected an error matching ${pattern}, compiled fine`);
    assert.match(msg, pattern);
}

const bake = F.loadJobType(path.join(scripts, "soak_bake.js"));
const anim = F.loadJobType(path.join(scripts, "soak_drying_animation.js"));
const bakeSettings = (over) => Object.assign(F.defaults(bake.jobType), {output_dir: "/farm/wet"}, over);
// The soak command lines of a task (its exec commands; each bake task starts
// with a make-directory of the output folder, checked below).
const argsOf = (task) => task.commands.filter((c) => c.name === "exec").map((c) => c.parameters.args);
const opt = (args, name) => args[args.indexOf(name) + 1];

// ---- the scripts themselves ----
check("checked-in scripts equal build_scripts.sh output", () => {
    fs.mkdirSync(tmp, {recursive: true});
    const out = fs.mkdtempSync(path.join(tmp, "scripts-"));
    execFileSync("sh", [path.join(root, "farm/flamenco/build_scripts.sh"), out]);
    for (const f of ["soak_bake.js", "soak_drying_animation.js"]) {
        assert.equal(fs.readFileSync(path.join(scripts, f), "utf8"), fs.readFileSync(path.join(out, f), "utf8"),
                     `${f} is stale: run farm/flamenco/build_scripts.sh`);
    }
});

check("job type names from the file names (scripts.go filenameToJobType)", () => {
    assert.equal(bake.name, "soak-bake");
    assert.equal(anim.name, "soak-drying-animation");
});

// goja (Flamenco 3's VM) runs ES5.1 plus the ES6 subset the shipped job types
// use; the scripts keep to that and to Flamenco's globals. Node-only or newer
// syntax is refused here even where a recent goja has it.
check("scripts use no Node API and no syntax beyond the shipped job types'", () => {
    const banned = [[/\brequire\s*\(/, "require()"], [/\bmodule\.exports\b/, "module.exports"],
        [/^\s*(import|export)\b/m, "ES modules"], [/\basync\b|\bawait\b/, "async/await"],
        [/\?\./, "optional chaining"], [/\?\?/, "nullish coalescing"], [/\.\.\.[A-Za-z_[]/, "spread/rest"],
        [/\bclass\s+[A-Za-z_]/, "class"], [/\bconsole\./, "console"], [/\bprocess\.env\b/, "process.env"],
        [/\b(Buffer|setTimeout|setInterval|globalThis)\b/, "Node/ES2020 globals"],
        [/\.(padStart|padEnd|includes|flat|flatMap|at)\(/, "ES2016+ methods"],
        [/\b(Object\.entries|Object\.values|Array\.from|Number\.isInteger)\b/, "ES2015+/2017 statics not in the shipped scripts"],
        [/\b(let|const|var)\s*[[{]/, "destructuring"]];
    for (const f of ["soak_bake.js", "soak_drying_animation.js"]) {
        // comment lines and the Python run in Blender out
        const code = fs.readFileSync(path.join(scripts, f), "utf8").replace(/const SOAK_PY_WETMAP = `[^`]*`/, "").split("\n")
            .filter((l) => !/^\s*\/\//.test(l)).join("\n");
        for (const [re, what] of banned) assert.doesNotMatch(code, re, `${f} uses ${what}`);
    }
});

check("JOB_TYPE settings follow Flamenco's AvailableJobSetting schema", () => {
    for (const jt of [bake.jobType, anim.jobType]) {
        assert.equal(typeof jt.label, "string");
        const keys = new Set();
        for (const s of jt.settings) {
            assert.ok(!keys.has(s.key), `duplicate key ${s.key}`);
            keys.add(s.key);
            assert.ok(["string", "int32", "float", "bool"].indexOf(s.type) >= 0, `${s.key}: type ${s.type}`);
            if (s.subtype) {
                assert.equal(s.type, "string");
                assert.ok(["file_path", "dir_path", "file_name", "hashed_file_path"].indexOf(s.subtype) >= 0);
            }
            if (s.visible) assert.ok(["visible", "hidden", "submission", "web"].indexOf(s.visible) >= 0);
            if (s.choices) {
                assert.equal(s.type, "string");
                assert.ok(s.choices.indexOf(s.default) >= 0, `${s.key}: default not a choice`);
            }
            if (s.evalInfo) {
                assert.equal(typeof s.evalInfo.showLinkButton, "boolean");
                assert.equal(typeof s.evalInfo.description, "string");
            }
            if (s.default !== undefined && s.type !== "string") {
                assert.equal(typeof s.default, s.type === "bool" ? "boolean" : "number", `${s.key} default`);
            }
        }
    }
});

// ---- soak-bake ----
// soak bakes frame f at --time + (f - --frame-origin) * --frame-time whatever
// its --frames range (bake_cli_common.c): every command must carry the job's
// own Time, Frame Time and first frame, so each frame gets one run's time.
function framesOfCommands(tasks, T, A, DT) {
    const seen = [];
    for (const task of tasks) {
        for (const args of argsOf(task)) {
            const [a, b] = opt(args, "--frames").split("-").map(Number);
            assert.equal(Number(opt(args, "--time")), T);
            assert.equal(Number(opt(args, "--frame-time")), DT);
            assert.equal(opt(args, "--frame-origin"), String(A));
            for (let f = a; f <= b; f++) seen.push(f);
        }
    }
    return seen;
}

check("drying 1-7, chunks of 3: tasks, commands, single-run times", () => {
    const {tasks} = bake.compile(bakeSettings({frames: "1-7", chunk_size: 3, width: 64, height: 48, seed: 5,
                                               time: 0.25, frame_time: 0.125, extra_args: "--t-fill 0.3 --noise '0.4'"}));
    assert.deepEqual(tasks.map((t) => t.name), ["bake-1-3", "bake-4-6", "bake-7"]);
    for (const t of tasks) {
        assert.equal(t.type, "misc");
        assert.deepEqual(t.dependencies, []);
        assert.deepEqual(t.commands[0], {name: "make-directory", parameters: {path: "/farm/wet"}, totalStepCount: 0});
        for (const c of t.commands.slice(1)) {
            assert.equal(c.name, "exec");
            assert.equal(c.parameters.exe, "{soak}");
            assert.ok(c.parameters.args.every((a) => typeof a === "string"), "exec args must be strings");
        }
    }
    assert.deepEqual(argsOf(tasks[1]), [["bake", "drying", "--width", "64", "--height", "48", "--seed", "5",
        "--t-fill", "0.3", "--noise", "0.4", "--frames", "4-6", "--time", "0.25", "--frame-time", "0.125",
        "--frame-origin", "1", "-o", "/farm/wet/wet.%04d.exr"]]);
    assert.equal(tasks[1].commands[1].totalStepCount, 3);
    assert.deepEqual(framesOfCommands(tasks, 0.25, 1, 0.125), [1, 2, 3, 4, 5, 6, 7]);
});

check("two-frame chunks come as '5,6' (frameRangeMerge) and bake as one run", () => {
    const {tasks} = bake.compile(bakeSettings({frames: "5-9", chunk_size: 2}));
    assert.deepEqual(tasks.map((t) => t.name), ["bake-5,6", "bake-7,8", "bake-9"]);
    assert.deepEqual(argsOf(tasks[0]).map((a) => opt(a, "--frames")), ["5-6"]);
    assert.deepEqual(framesOfCommands(tasks, 0, 5, 0.01), [5, 6, 7, 8, 9]);
});

check("a gap in the frames: one command per run, all with the job's time and origin", () => {
    const {tasks} = bake.compile(bakeSettings({frames: "10, 1-3", chunk_size: 10, time: 0.5, frame_time: 0.0625}));
    assert.deepEqual(tasks.map((t) => t.name), ["bake-1-3,10"]);
    const a = argsOf(tasks[0]);
    assert.deepEqual(a.map((x) => opt(x, "--frames")), ["1-3", "10-10"]);
    assert.deepEqual(framesOfCommands(tasks, 0.5, 1, 0.0625), [1, 2, 3, 10]);
});

// At time 0 and frame time 0.01 the former per-chunk times (chunk 11-20 at
// --time 0.1) rounded differently from one run's further on, which took 19
// soak runs for these 6 chunks; with --frame-origin each chunk is one run.
check("frames 1-60 in chunks of 10: one soak run per chunk, Time and origin of the job", () => {
    const {tasks} = bake.compile(bakeSettings({frames: "1-60", chunk_size: 10, time: 0, frame_time: 0.01}));
    assert.deepEqual(tasks.map((t) => argsOf(t).length), [1, 1, 1, 1, 1, 1]);
    assert.deepEqual(argsOf(tasks[5]).map((a) => opt(a, "--frames")), ["51-60"]);
    assert.deepEqual(framesOfCommands(tasks, 0, 1, 0.01), Array.from({length: 60}, (_, i) => i + 1));
});

check("drying with a mask: the mask sets the size (no --width/--height)", () => {
    const {tasks} = bake.compile(bakeSettings({frames: "1-2", input: "/farm/masks/splash.png"}));
    const a = argsOf(tasks[0])[0];
    assert.deepEqual(a.slice(0, 3), ["bake", "drying", "/farm/masks/splash.png"]);
    assert.ok(a.indexOf("--width") < 0 && a.indexOf("--height") < 0);
});

check("turbulence and waves chunk like drying; threads passed when set", () => {
    for (const kind of ["turbulence", "waves"]) {
        const {tasks} = bake.compile(bakeSettings({kind, frames: "0-3", chunk_size: 4, threads: 2}));
        assert.equal(tasks.length, 1);
        const a = argsOf(tasks[0])[0];
        assert.deepEqual(a.slice(0, 2), ["bake", kind]);
        assert.equal(opt(a, "--threads"), "2");
        assert.equal(opt(a, "--frames"), "0-3");
    }
});

check("drops and rain-frames chunk like drying: the input (optional mesh / required mesh) after the command", () => {
    const drops = bake.compile(bakeSettings({kind: "drops", frames: "0-5", chunk_size: 3, width: 32, height: 32,
                                             frame_time: 0.5})).tasks;
    assert.deepEqual(drops.map((t) => t.name), ["bake-0-2", "bake-3-5"]);
    assert.deepEqual(argsOf(drops[1])[0].slice(0, 3), ["bake", "drops", "--width"]);
    assert.equal(opt(argsOf(drops[1])[0], "--frame-origin"), "0");
    const rain = bake.compile(bakeSettings({kind: "rain-frames", input: "/farm/wall.obj", frames: "0-3", chunk_size: 2,
                                            width: 64, height: 64, frame_time: 25, extra_args: "--up z"})).tasks;
    assert.equal(rain.length, 2);
    assert.deepEqual(argsOf(rain[1]), [["bake", "rain", "/farm/wall.obj", "--width", "64", "--height", "64", "--seed",
        "0", "--up", "z", "--frames", "2-3", "--time", "0", "--frame-time", "25", "--frame-origin", "0", "-o",
        "/farm/wet/wet.%04d.exr"]]);
});

check("rain: one task, one map, the mesh as input", () => {
    const {tasks} = bake.compile(bakeSettings({kind: "rain", input: "/farm/statue.glb", output_name: "rain.exr",
                                               width: 256, height: 256}));
    assert.deepEqual(tasks.map((t) => t.name), ["bake-rain"]);
    assert.deepEqual(tasks[0].commands[0].parameters, {path: "/farm/wet"});
    assert.deepEqual(argsOf(tasks[0]), [["bake", "rain", "/farm/statue.glb", "--width", "256", "--height", "256",
                                         "--seed", "0", "-o", "/farm/wet/rain.exr"]]);
});

check("bad settings are refused naming the setting", () => {
    const bad = [
        [{kind: "snow"}, /"kind".*snow/],
        [{frames: "a-b"}, /"frames"/],
        [{frames: ""}, /"frames"/],
        [{frames: "-3"}, /"frames"/],
        [{chunk_size: 0, frames: "1-3"}, /"chunk_size"/],
        [{chunk_size: 2.5, frames: "1-3"}, /"chunk_size"/],
        [{frames: "1-3", output_name: "wet.exr"}, /"output_name".*frame number pattern/],
        [{frames: "1-3", output_name: "wet.%04d.%d.exr"}, /"output_name"/],
        [{frames: "1-3", output_name: "sub/wet.%04d.exr"}, /"output_name".*without folders/],
        [{frames: "1-3", output_dir: ""}, /"output_dir"/],
        [{kind: "rain", output_name: "rain.exr"}, /"input".*mesh/],
        [{kind: "rain", input: "/m.obj"}, /"output_name".*single map/],
        [{kind: "rain-frames", frames: "1-3"}, /"input".*mesh/],
        [{kind: "rain-frames", frames: "1-3", input: "/m.obj", output_name: "rain.exr"}, /"output_name".*pattern/],
        [{kind: "drops", frames: "1-3", time: -1}, /"time".*rain's start/],
        [{frames: "1-3", extra_args: "--t-fill 0.3 -o /tmp/x.%04d.exr"}, /"extra_args".*"-o"/],
        [{frames: "1-3", extra_args: "--frames=1-2"}, /"extra_args".*"--frames"/],
        [{frames: "1-3", extra_args: "--frame-origin 0"}, /"extra_args".*"--frame-origin"/],
        [{frames: "1-3", extra_args: "--noise 'unclosed"}, /"extra_args".*cannot split/],
        [{frames: "1-3", time: -0.5}, /"time".*drying/],
        [{frames: "1-3", frame_time: Number.NaN}, /"frame_time"/],
        [{frames: "1-3", width: 0}, /"width"/],
        [{frames: "1-3", seed: -1}, /"seed"/],
    ];
    for (const [over, re] of bad) throwsWith(() => bake.compile(bakeSettings(over)), re);
});

// ---- soak-drying-animation ----
const animSettings = (over) => Object.assign(F.defaults(anim.jobType), {
    frames: "1-4", chunk_size: 2, bake_chunk_size: 3, width: 32, height: 32, frame_time: 0.25,
    render_output_root: "/farm/render", render_output_path: "/farm/render/shot/{timestamp}/######",
    blendfile: "/farm/shot.blend", format: "PNG", scene: "Scene"}, over);

check("animation: bake chunks, render chunks depending on the bakes of their frames", () => {
    const created = new Date(2026, 10, 25, 3, 4, 5);
    const {tasks, settings} = anim.compile(animSettings({}), created);
    assert.deepEqual(tasks.map((t) => `${t.name}:${t.type}`),
                     ["bake-1-3:misc", "bake-4:misc", "render-1,2:blender", "render-3,4:blender"]);
    const id = (name) => tasks.find((t) => t.name === name).uuid;
    assert.deepEqual(tasks[2].dependencies, [id("bake-1-3")]);
    assert.deepEqual(tasks[3].dependencies, [id("bake-1-3"), id("bake-4")]);
    assert.equal(settings.render_output_path, "/farm/render/shot/2026-11-25_030405/######");
    const wet = "/farm/render/shot/2026-11-25_030405/wetmap/wet.%04d.exr";
    assert.equal(tasks[1].commands[0].parameters.path, "/farm/render/shot/2026-11-25_030405/wetmap");
    assert.deepEqual(argsOf(tasks[1]), [["bake", "drying", "--width", "32", "--height", "32", "--seed", "0",
        "--t-fill", "0.2", "--noise", "0.3", "--frames", "4-4", "--time", "0", "--frame-time", "0.25",
        "--frame-origin", "1", "-o", wet]]);
    const r = tasks[3].commands[0];
    assert.equal(r.name, "blender-render");
    assert.equal(r.parameters.exe, "{blender}");
    assert.equal(r.parameters.exeArgs, "{blenderArgs}");
    assert.equal(r.parameters.blendfile, "/farm/shot.blend");
    assert.equal(r.totalStepCount, 2);
    const a = r.parameters.args;
    assert.deepEqual(a.slice(0, 3), ["--python-exit-code", "1", "--python-expr"]);
    assert.deepEqual(a.slice(4), ["--scene", "Scene", "--render-output", "/farm/render/shot/2026-11-25_030405/######",
        "--render-format", "PNG", "--render-frame", "3,4", "--", wet, "1", "4", ""]);
    assert.match(a[3], /soak_role/);
    assert.doesNotMatch(a[3], /[{}]/, "Flamenco's variable expansion would touch braces");
});

check("animation: render chunks of 3+ frames use Blender's '..'", () => {
    const {tasks} = anim.compile(animSettings({frames: "1-6", chunk_size: 3, bake_chunk_size: 2}));
    const r = tasks.filter((t) => t.type === "blender");
    assert.deepEqual(r.map((t) => opt(t.commands[0].parameters.args, "--render-frame")), ["1..3", "4..6"]);
    assert.deepEqual(r.map((t) => t.dependencies.length), [2, 2]);
});

check("animation: bad settings are refused naming the setting", () => {
    const bad = [
        [{blendfile: ""}, /"blendfile"/],
        [{format: "FFMPEG"}, /"format"/],
        [{render_output_path: ""}, /"render_output_path"/],
        [{t_fill: 2}, /"t_fill"/],
        [{noise: -0.1}, /"noise"/],
        [{time: -1}, /"time"/],
        [{bake_chunk_size: 0}, /"bake_chunk_size"/],
        [{extra_bake_args: "--seed 3"}, /"extra_bake_args".*"--seed"/],
    ];
    for (const [over, re] of bad) throwsWith(() => anim.compile(animSettings(over)), re);
});

check("stand-in frameChunker follows Flamenco's js_globals_test.go examples", () => {
    assert.deepEqual(F.frameChunker("1..10,20..25,40", 4), ["1-4", "5-8", "9,10,20,21", "22-25", "40"]);
    assert.deepEqual(F.frameChunker("1-3", 5), ["1-3"]);
    assert.throws(() => F.frameChunker("", 1));
    assert.throws(() => F.frameChunker("1-3", 0));
});

console.log(`${checks - failures}/${checks} checks passed`);
process.exit(failures ? 1 : 0);

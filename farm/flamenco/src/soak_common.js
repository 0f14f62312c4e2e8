// ---- Shared by the Soak job types (farm/flamenco/src/soak_common.js) ----
// Flamenco runs each job-type file in its own goja VM in strict mode, with no
// require(): helpers cannot be shared at run time, so build_scripts.sh prepends
// this file to each job type and a test fails when a copy is stale.
// Written for goja: ES5.1 plus the ES6 the shipped job types use (const/let,
// arrow functions, template literals, for-of, Set); nothing from Node.

// soak bake options the job types set themselves; refused in extra arguments.
const SOAK_OWNED_OPTIONS = new Set(["-o", "--output", "--frames", "--time", "--frame-time", "--frame-origin",
    "--seed", "--width", "--height", "--threads", "--help", "-h"]);

function soakFail(setting, message) {
    throw `Soak: setting "${setting}": ${message}`;
}

function soakInteger(settings, key, lo, hi) {
    const v = Number(settings[key]);
    if (!(Math.floor(v) === v && v >= lo && v <= hi)) {
        soakFail(key, `expected a whole number in [${lo}, ${hi}], got "${settings[key]}"`);
    }
    return v;
}

function soakNumber(settings, key, lo, hi) {
    const v = Number(settings[key]);
    if (!(v >= lo && v <= hi)) {
        soakFail(key, `expected a number in [${lo}, ${hi}], got "${settings[key]}"`);
    }
    return v;
}

function soakText(settings, key) {
    const v = settings[key];
    return v === undefined || v === null ? "" : String(v).trim();
}

// Frame numbers of a frameChunker chunk such as "1-3", "5,6" or "1-3,7",
// as runs [first, last] of consecutive frames (soak's --frames takes one run;
// frameChunker writes two consecutive frames as "5,6").
function soakChunkRuns(chunk) {
    const runs = [];
    for (const part of String(chunk).split(",")) {
        const ends = part.split("-");
        const first = Number(ends[0]);
        const last = ends.length > 1 ? Number(ends[1]) : first;
        if (runs.length > 0 && runs[runs.length - 1][1] + 1 === first) runs[runs.length - 1][1] = last;
        else runs.push([first, last]);
    }
    return runs;
}

// Every frame of the job, sorted; frames must be soak's (0 .. 9999999).
function soakJobFrames(frames) {
    const list = [];
    let chunks;
    try {
        chunks = frameChunker(frames, 1);
    } catch (e) {
        soakFail("frames", `cannot read "${frames}" (examples: "1-120", "1-10,20-30"): ${e}`);
    }
    for (const c of chunks) {
        const f = Number(c);
        if (!(Math.floor(f) === f && f >= 0 && f <= 9999999)) {
            soakFail("frames", `frame "${c}" is outside soak's 0 .. 9999999`);
        }
        list.push(f);
    }
    if (list.length === 0) soakFail("frames", "no frames");
    return list;
}

function soakChunks(frames, settings, key) {
    const size = soakInteger(settings, key, 1, 100000);
    const chunks = [];
    for (const c of frameChunker(frames, size)) chunks.push(String(c));
    return chunks;
}

// A soak output pattern holds exactly one %d, %Nd or %0Nd (and %% for '%').
function soakCheckPattern(key, name, wantPattern) {
    const rest = name.replace(/%%/g, "");
    const convs = rest.match(/%0?[0-9]?d/g) || [];
    const stray = rest.replace(/%0?[0-9]?d/g, "").indexOf("%") >= 0;
    if (wantPattern && (convs.length !== 1 || stray)) {
        soakFail(key, `"${name}" needs one frame number pattern such as wet.%04d.exr`);
    }
    if (!wantPattern && (convs.length !== 0 || stray)) {
        soakFail(key, `"${name}" is one file (no frame pattern): this bake makes a single map`);
    }
}

function soakExtraArgs(settings, key) {
    const text = soakText(settings, key);
    let args;
    try {
        args = text === "" ? [] : shellSplit(text);
    } catch (e) {
        soakFail(key, `cannot split "${text}": ${e}`);
    }
    const out = [];
    for (const a of args) {
        const name = String(a).split("=")[0];
        if (SOAK_OWNED_OPTIONS.has(name)) {
            soakFail(key, `"${name}" is set by the job's own settings; remove it from the extra arguments`);
        }
        out.push(String(a));
    }
    return out;
}

// Arguments of `soak bake KIND` common to every command of a job.
function soakSizeSeedArgs(settings, withSize) {
    const args = [];
    if (withSize) {
        args.push("--width", String(soakInteger(settings, "width", 1, 16384)),
                  "--height", String(soakInteger(settings, "height", 1, 16384)));
    }
    args.push("--seed", String(soakInteger(settings, "seed", 0, 2147483647)));
    const threads = settings.threads === undefined ? 0 : soakInteger(settings, "threads", 0, 1024);
    if (threads > 0) args.push("--threads", String(threads));
    return args;
}

// soak writes into an existing folder: the worker's make-directory (MkdirAll)
// first, in every task, so that any task can run first or again.
function soakMakeOutputDir(output) {
    return author.Command("make-directory", {path: path.dirname(output)});
}

// Bake tasks ("misc": Flamenco's type of the exec command) for every chunk of
// the job's frames; one exec command per run of consecutive frames (one per
// chunk unless the job's frames have gaps). Every command gets the job's
// Time and Frame Time with --frame-origin = the job's first frame: soak bakes
// frame f at Time + (f - origin) * Frame Time whatever the --frames range, so
// each chunk's maps equal those of one soak run over the whole job.
function soakAuthorBakeTasks(frames, chunks, kindArgs, timing, outPattern) {
    const tasks = [];
    for (const chunk of chunks) {
        const task = author.Task(`bake-${chunk}`, "misc");
        task.addCommand(soakMakeOutputDir(outPattern));
        const runs = [];
        for (const run of soakChunkRuns(chunk)) runs.push({first: run[0], last: run[1]});
        for (const r of runs) {
            const args = kindArgs.concat(["--frames", `${r.first}-${r.last}`, "--time", String(timing.time),
                "--frame-time", String(timing.frameTime), "--frame-origin", String(timing.first), "-o", outPattern]);
            task.addCommand(author.Command("exec", {exe: "{soak}", args: args}, r.last - r.first + 1));
        }
        tasks.push({task: task, runs: runs, chunk: chunk});
    }
    return tasks;
}
// ---- end of the shared part ----

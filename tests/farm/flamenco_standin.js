// A minimal stand-in for the parts of Flamenco 3's Manager that a job-type
// script sees, written from Flamenco's source and documentation (paths below
// are in Flamenco's repository, internal/manager/job_compilers/ unless said):
//
// - scripts.go loadScriptsFrom: each scripts/*.js is compiled with
//   goja.Compile(name, src, strict=true) and run in a fresh VM; the job type's
//   name is the file name with '_' -> '-'. Here: node:vm, a fresh context,
//   "use strict" prepended. A fresh context has no require, console, process
//   or Buffer, so a script leaning on Node fails here as in goja.
// - scripts.go newGojaVM: globals print, alert, frameChunker, frameCount,
//   formatTimestampLocal, shellSplit, author, path, process (only cwd and
//   platform, js_process.go).
// - js_globals.go jsFrameChunker/frameRangeExplode/frameRangeMerge: "A-B" and
//   "A..B" ranges, comma lists, duplicates dropped, sorted; chunks of at most
//   chunkSize frames, each merged back with "-" for 3+ consecutive frames and
//   "," otherwise (two frames give "5,6"); errors for empty input, chunk size
//   < 1, unparsable parts. jsFrameCount: number of frames of a range.
// - js_globals.go jsShellSplit: github.com/google/shlex (whitespace, quotes,
//   backslash escapes); here the subset: '...', "..." and \ escapes.
// - js_path.go + pkg/crosspath: join = Go path.Join (cleaned) with '\' -> '/',
//   dirname = everything before the last '/', basename = Go path.Base, stem.
// - author.go: author.Task(name, type) (both required, trimmed),
//   author.Command(name, parameters, totalStepCount), task.addCommand,
//   task.addDependency, job.addTask -- which appends a COPY of the task
//   (aj.Tasks = append(aj.Tasks, *at)): commands added afterwards are lost,
//   dependencies are pointers to the depended-on task.
// - job_compilers.go getCompileJob: compileJob(job) with job.settings the
//   submitted settings map; a thrown value is the compile error.
// - api_impl/varrepl.go replaceTaskVariables: before a task goes to a worker,
//   "{name}" of every Manager variable is replaced in string and string-array
//   command parameters (expandTask below).
"use strict";
const fs = require("node:fs");
const vm = require("node:vm");

function frameRangeExplode(range) {
    const frames = new Set();
    for (const part of String(range).replace(/\.\./g, "-").split(",")) {
        const ends = part.split("-");
        const parse = (s) => {
            const t = s.trim();
            if (!/^[+-]?[0-9]+$/.test(t)) throw new Error(`invalid range "${range}": ${part}`);
            return parseInt(t, 10);
        };
        if (ends.length === 1) frames.add(parse(ends[0]));
        else if (ends.length === 2) {
            const a = parse(ends[0]), b = parse(ends[1]);
            for (let f = a; f <= b; f++) frames.add(f);
        } else throw new Error(`invalid range "${range}": ${part}`);
    }
    return Array.from(frames).sort((x, y) => x - y);
}

function frameRangeMerge(frames) {
    const out = [];
    const append = (a, b) => {
        if (a === b) out.push(String(a));
        else if (a + 1 === b) out.push(String(a), String(b));
        else out.push(`${a}-${b}`);
    };
    let start = frames[0], prev = frames[0];
    for (const f of frames) {
        if (f > prev + 1) {
            append(start, prev);
            start = f;
        }
        prev = f;
    }
    append(start, prev);
    return out.join(",");
}

function frameChunker(range, chunkSize) {
    const r = String(range).trim();
    if (r.length === 0) throw new Error(`invalid range "": empty range`);
    if (chunkSize < 1) throw new Error(`invalid chunk size, must be positive number: ${chunkSize}`);
    const frames = frameRangeExplode(r);
    if (frames.length === 0) throw new Error(`invalid range "${r}": empty range`);
    const chunks = [];
    for (let i = 0; i < frames.length; i += chunkSize) chunks.push(frameRangeMerge(frames.slice(i, i + chunkSize)));
    return chunks;
}

function shellSplit(text) {
    const out = [];
    let cur = null, i = 0;
    while (i < text.length) {
        const c = text[i];
        if (/\s/.test(c)) {
            if (cur !== null) out.push(cur), cur = null;
            i++;
        } else if (c === "'" || c === '"') {
            const end = text.indexOf(c, i + 1);
            if (end < 0) throw new Error("EOF found when expecting closing quote");
            cur = (cur || "") + text.slice(i + 1, end);
            i = end + 1;
        } else if (c === "\\") {
            if (i + 1 >= text.length) throw new Error("EOF found after escape character");
            cur = (cur || "") + text[i + 1];
            i += 2;
        } else {
            cur = (cur || "") + c;
            i++;
        }
    }
    if (cur !== null) out.push(cur);
    return out;
}

// Go's path.Clean of a '/'-separated path.
function goClean(p) {
    if (p === "") return ".";
    const rooted = p[0] === "/";
    const parts = [];
    for (const s of p.split("/")) {
        if (s === "" || s === ".") continue;
        if (s === "..") {
            if (parts.length && parts[parts.length - 1] !== "..") parts.pop();
            else if (!rooted) parts.push("..");
        } else parts.push(s);
    }
    const body = parts.join("/");
    return rooted ? "/" + body : (body || ".");
}

const toSlash = (p) => String(p).replace(/\\/g, "/");
const pathModule = {
    join: (...elems) => {
        const kept = elems.map(String).filter((e) => e !== "");
        return kept.length ? toSlash(goClean(kept.join("/").replace(/\\/g, "/"))) : "";
    },
    dirname: (p) => {
        if (p === "") return ".";
        const s = toSlash(p), i = s.lastIndexOf("/");
        if (i < 0) return ".";
        return i === 0 ? "/" : s.slice(0, i);
    },
    basename: (p) => {
        let s = toSlash(p);
        if (s === "") return ".";
        while (s.length > 1 && s.endsWith("/")) s = s.slice(0, -1);
        if (s === "/") return "/";
        return s.slice(s.lastIndexOf("/") + 1);
    },
    stem: (p) => {
        const b = pathModule.basename(p), dot = b.lastIndexOf(".");
        return dot > 0 ? b.slice(0, dot) : b;
    },
};

let uuidCounter = 0;
function makeAuthor() {
    return {
        Task(name, type) {
            name = String(name).trim();
            type = String(type).trim();
            if (!name) throw new Error("author.Task(name, type): name is required");
            if (!type) throw new Error("author.Task(name, type): type is required");
            const task = {uuid: `task-${++uuidCounter}`, name, type, priority: 50, commands: [], dependencies: []};
            task.addCommand = (cmd) => { task.commands.push(cmd); };
            task.addDependency = (dep) => { task.dependencies.push(dep); };
            return task;
        },
        Command(name, parameters, totalStepCount) {
            return {name, parameters, totalStepCount: totalStepCount || 0};
        },
    };
}

function formatTimestampLocal(date) {
    const d = date instanceof Date ? date : new Date(date);
    const p = (n) => String(n).padStart(2, "0");
    return `${d.getFullYear()}-${p(d.getMonth() + 1)}-${p(d.getDate())}_${p(d.getHours())}${p(d.getMinutes())}${p(d.getSeconds())}`;
}

// Loads a job-type script as the Manager does; returns {name, jobType, compile}.
function loadJobType(file) {
    const src = fs.readFileSync(file, "utf8");
    const log = [];
    const context = vm.createContext({
        print: (...a) => log.push(a.join(" ")),
        alert: (...a) => log.push("ALERT " + a.join(" ")),
        frameChunker, frameCount: (r) => frameRangeExplode(r).length, formatTimestampLocal, shellSplit,
        author: makeAuthor(), path: pathModule, process: {cwd: () => "/", platform: "linux"},
    });
    const script = new vm.Script(`"use strict";\n${src}\n;({JOB_TYPE: JOB_TYPE, compileJob: compileJob});`,
                                 {filename: file});
    const exported = script.runInContext(context);
    const name = file.split("/").pop().replace(/\.js$/, "").replace(/_/g, "-");
    return {
        name,
        jobType: exported.JOB_TYPE,
        log,
        // Compiles a job; returns {tasks, settings} where each task is the
        // snapshot job.addTask() took, or throws the script's error.
        compile(settings, created) {
            const tasks = [];
            const job = {
                name: "test-job", settings: Object.assign({}, settings), created: created || new Date(),
                addTask: (t) => tasks.push({uuid: t.uuid, name: t.name, type: t.type,
                                            commands: t.commands.slice(), dependencies: t.dependencies.map((d) => d.uuid)}),
            };
            exported.compileJob(job);
            // The Manager stores the authored job as JSON (plain data from here on).
            return JSON.parse(JSON.stringify({tasks, settings: job.settings}));
        },
    };
}

// The JOB_TYPE defaults, as the submitter fills unset settings.
function defaults(jobType) {
    const out = {};
    for (const s of jobType.settings) if (s.default !== undefined) out[s.key] = s.default;
    return out;
}

// Manager variable replacement for one worker (varrepl.go).
function expandTask(task, variables) {
    const exp = (s) => s.replace(/{([^}]+)}/g, (m, name) => (name in variables ? variables[name] : m));
    return Object.assign({}, task, {
        commands: task.commands.map((c) => {
            const params = {};
            for (const [k, v] of Object.entries(c.parameters)) {
                if (typeof v === "string") params[k] = exp(v);
                else if (Array.isArray(v)) params[k] = v.map((x) => (typeof x === "string" ? exp(x) : x));
                else params[k] = v;
            }
            return Object.assign({}, c, {parameters: params});
        }),
    });
}

// Tasks in an order that respects every dependency (the Manager's scheduler
// hands out a task only when its dependencies are done); fails on a cycle or
// on a dependency that is not a task of the job.
function dependencyOrder(tasks) {
    const byId = new Map(tasks.map((t) => [t.uuid, t]));
    const done = new Set(), order = [];
    while (order.length < tasks.length) {
        const ready = tasks.filter((t) => !done.has(t.uuid) && t.dependencies.every((d) => done.has(d)));
        if (ready.length === 0) throw new Error("dependency cycle or dependency outside the job");
        for (const t of ready) for (const d of t.dependencies) if (!byId.has(d)) throw new Error("unknown dependency");
        for (const t of ready) done.add(t.uuid), order.push(t);
    }
    return order;
}

// The argv a worker runs for a command (worker/command_exec.go,
// command_blender.go); null for make-directory, which the worker does itself
// (command_file_mgmt.go: os.MkdirAll(path)) and runCommand below does too.
function commandArgv(cmd) {
    const p = cmd.parameters;
    if (cmd.name === "make-directory") return null;
    if (cmd.name === "exec") return [p.exe].concat(p.args.map(String));
    if (cmd.name === "blender-render") {
        const exeArgs = p.exeArgs ? shellSplit(p.exeArgs) : [];
        return [p.exe].concat(exeArgs, p.argsBefore.map(String), p.blendfile ? [p.blendfile] : [], p.args.map(String));
    }
    throw new Error(`command ${cmd.name} not run by this stand-in`);
}

function runMakeDirectory(cmd) {
    if (!cmd.parameters.path) throw new Error("make-directory: missing 'path' parameter");
    fs.mkdirSync(cmd.parameters.path, {recursive: true, mode: 0o775});
}

module.exports = {runMakeDirectory, loadJobType, defaults, expandTask, dependencyOrder, commandArgv, frameChunker, shellSplit,
                  pathModule};

const JOB_TYPE = {
    label: "Soak Wet-Map Bake",
    description: "Bake Soak wet maps with soak bake: drying, turbulence, waves, raindrops and rain-over-time image sequences in chunks of frames, or one rain map",
    settings: [
        { key: "kind", type: "string", required: true, default: "drying",
          choices: ["drying", "turbulence", "waves", "drops", "rain-frames", "rain"],
          description: "What to bake: drying (a wet region drying), turbulence (noise patches), waves (a beach's wet sand), drops (raindrops spotting a surface, then drying), rain-frames (a mesh wetting in rain and its running film, over time), rain (a mesh's rain wetting, one map)" },
        { key: "frames", type: "string", required: true,
          eval: "f'{C.scene.frame_start}-{C.scene.frame_end}'",
          evalInfo: { showLinkButton: true, description: "Scene frame range" },
          description: "Frames to bake, e.g. '1-120' or '1-10,20-30' (rain: unused)" },
        { key: "chunk_size", type: "int32", default: 10, propargs: {min: 1, max: 100000}, visible: "submission",
          description: "Frames baked by one task" },
        { key: "input", type: "string", subtype: "file_path", default: "",
          description: "drying: optional mask image (texels above the threshold start wet; it sets the size); drops: optional mesh (its sky exposure weights the impacts); rain and rain-frames: the mesh, with UVs (required)" },
        { key: "output_dir", type: "string", subtype: "dir_path", required: true, visible: "submission",
          description: "Folder of the baked maps, on storage every worker reads and writes" },
        { key: "output_name", type: "string", subtype: "file_name", required: true, default: "wet.%04d.exr",
          description: "File name; sequences need a frame number pattern (%04d); .exr (half float), .png/.tif (16-bit linear) or .tx" },
        { key: "width", type: "int32", default: 1024, propargs: {min: 1, max: 16384},
          description: "Map width in texels (drying with a mask: the mask's)" },
        { key: "height", type: "int32", default: 1024, propargs: {min: 1, max: 16384},
          description: "Map height in texels (drying with a mask: the mask's)" },
        { key: "seed", type: "int32", default: 0, propargs: {min: 0},
          description: "Noise seed: the same seed gives the same maps on any worker and thread count" },
        { key: "time", type: "float", default: 0.0,
          description: "Time of the first frame of the range (drying: 0 wet, 1 dry; turbulence and waves: their animation time; drops and rain-frames: seconds since the rain began)" },
        { key: "frame_time", type: "float", default: 0.01, propargs: {min: 0.0},
          description: "Time between frames: frame f bakes at Time + (f - first frame) * Frame Time, as one soak run would" },
        { key: "threads", type: "int32", default: 0, propargs: {min: 0, max: 1024}, visible: "submission",
          description: "Threads per task, 0 = every core of the worker (the maps do not depend on it)" },
        { key: "extra_args", type: "string", default: "",
          description: "Further options of the kind, e.g. '--t-fill 0.3 --noise 0.4' (soak bake KIND --help)" },
    ]
};

const SOAK_SEQUENCE_KINDS = ["drying", "turbulence", "waves", "drops", "rain-frames"];
// The soak bake command of each kind, where the names differ.
const SOAK_KIND_COMMAND = {"rain-frames": "rain"};

function compileJob(job) {
    print("Soak wet-map bake job submitted");
    const settings = job.settings;
    const kind = soakText(settings, "kind");
    if (kind !== "rain" && SOAK_SEQUENCE_KINDS.indexOf(kind) < 0) {
        soakFail("kind", `expected drying, turbulence, waves, drops, rain-frames or rain, got "${kind}"`);
    }
    const outputDir = soakText(settings, "output_dir");
    if (outputDir === "") soakFail("output_dir", "an output folder is required");
    const outputName = soakText(settings, "output_name");
    if (outputName === "" || outputName.indexOf("/") >= 0 || outputName.indexOf("\\") >= 0) {
        soakFail("output_name", `expected a file name without folders, got "${outputName}"`);
    }
    soakCheckPattern("output_name", outputName, kind !== "rain");
    const input = soakText(settings, "input");
    const extra = soakExtraArgs(settings, "extra_args");
    const output = path.join(outputDir, outputName);

    if (kind === "rain") {
        if (input === "") soakFail("input", "rain needs the mesh to bake (OBJ, PLY, glTF...)");
        const task = author.Task("bake-rain", "misc");
        task.addCommand(soakMakeOutputDir(output));
        const args = ["bake", "rain", input].concat(soakSizeSeedArgs(settings, true), extra, ["-o", output]);
        task.addCommand(author.Command("exec", {exe: "{soak}", args: args}));
        job.addTask(task);
        return;
    }

    const frames = soakJobFrames(settings.frames);
    const timing = {
        first: frames[0],
        time: soakNumber(settings, "time", -1e9, 1e9),
        frameTime: soakNumber(settings, "frame_time", 0, 1e6),
    };
    if (kind === "drying" && !(timing.time >= 0)) {
        soakFail("time", `drying time starts at 0 (wet), got ${timing.time}`);
    }
    if (kind === "rain-frames" && input === "") soakFail("input", "rain-frames needs the mesh to bake (OBJ, PLY, glTF...)");
    if ((kind === "drops" || kind === "rain-frames") && !(timing.time >= 0)) {
        soakFail("time", `${kind} time counts from the rain's start (0), got ${timing.time}`);
    }
    const inputTakesSize = kind === "drying" && input !== "";
    let kindArgs = ["bake", SOAK_KIND_COMMAND[kind] || kind];
    if (input !== "" && kind !== "turbulence" && kind !== "waves") kindArgs.push(input);
    kindArgs = kindArgs.concat(soakSizeSeedArgs(settings, !inputTakesSize), extra);

    const chunks = soakChunks(settings.frames, settings, "chunk_size");
    for (const t of soakAuthorBakeTasks(frames, chunks, kindArgs, timing, output)) {
        job.addTask(t.task);
    }
}

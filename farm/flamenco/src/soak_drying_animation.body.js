const JOB_TYPE = {
    label: "Soak Drying Animation",
    description: "Bake a drying wet-map sequence with soak bake drying, then render the frames in Blender with the Soak add-on's Image wetness source reading it",
    settings: [
        // Settings for artists to determine:
        { key: "frames", type: "string", required: true,
          eval: "f'{C.scene.frame_start}-{C.scene.frame_end}'",
          evalInfo: { showLinkButton: true, description: "Scene frame range" },
          description: "Frames to bake and render, e.g. '1-120'" },
        { key: "chunk_size", type: "int32", default: 1, propargs: {min: 1, max: 100000}, visible: "submission",
          description: "Frames rendered by one Blender task" },
        { key: "bake_chunk_size", type: "int32", default: 25, propargs: {min: 1, max: 100000}, visible: "submission",
          description: "Wet maps baked by one soak task (a map takes far less time than a render)" },
        { key: "mask", type: "string", subtype: "file_path", default: "", visible: "submission",
          description: "Wet region: an image whose texels above 0.5 start wet (it sets the map size); empty: the whole surface, dried in the noise's order" },
        { key: "width", type: "int32", default: 1024, propargs: {min: 1, max: 16384}, visible: "submission",
          description: "Wet-map width without a mask" },
        { key: "height", type: "int32", default: 1024, propargs: {min: 1, max: 16384}, visible: "submission",
          description: "Wet-map height without a mask" },
        { key: "seed", type: "int32", default: 0, propargs: {min: 0}, visible: "submission",
          description: "Noise seed of the drying order" },
        { key: "t_fill", type: "float", default: 0.2, propargs: {min: 0.0, max: 1.0}, visible: "submission",
          description: "Pore emptying time of a texel, as a fraction of the drying (0 = a sharp front)" },
        { key: "noise", type: "float", default: 0.3, propargs: {min: 0.0, max: 1.0}, visible: "submission",
          description: "Fraction of noise in the drying order (0 = from the borders inwards)" },
        { key: "time", type: "float", default: 0.0, propargs: {min: 0.0}, visible: "submission",
          description: "Drying time at the first frame (0 = all wet, 1 = all dry)" },
        { key: "frame_time", type: "float", default: 0.01, propargs: {min: 0.0},
          eval: "1.0 / max(1, C.scene.frame_end - C.scene.frame_start)",
          evalInfo: { showLinkButton: true, description: "Dry at the scene's last frame" },
          description: "Drying time between frames" },
        { key: "extra_bake_args", type: "string", default: "", visible: "submission",
          description: "Further soak bake drying options, e.g. '--noise-frequency 4' (soak bake drying --help)" },
        { key: "material", type: "string", default: "", visible: "submission",
          description: "Material whose Soak Image wetness source reads the baked maps; empty: every such material" },

        // render_output_root + add_path_components determine the value of render_output_path.
        { key: "render_output_root", type: "string", subtype: "dir_path", required: true, visible: "submission",
          description: "Base directory of where render output is stored. Will have some job-specific parts appended to it" },
        { key: "add_path_components", type: "int32", required: true, default: 0, propargs: {min: 0, max: 32}, visible: "submission",
          description: "Number of path components of the current blend file to use in the render output path" },
        { key: "render_output_path", type: "string", subtype: "file_path", editable: false,
          eval: "str(Path(abspath(settings.render_output_root), last_n_dir_parts(settings.add_path_components), jobname, '{timestamp}', '######'))",
          description: "Final file path of where render output will be saved; the wet maps go to its folder's 'wetmap' folder" },

        // Automatically evaluated settings:
        { key: "blendfile", type: "string", required: true, description: "Path of the Blend file to render", visible: "web" },
        { key: "format", type: "string", required: true, eval: "C.scene.render.image_settings.file_format", visible: "web" },
        { key: "scene", type: "string", required: true, eval: "C.scene.name", visible: "web",
          description: "Name of the scene to render." },
    ]
};

// Run inside Blender before --render-frame: points the Image wetness source
// (the add-on's image node tagged soak_role = "source") of the Soak materials
// at the baked sequence, so that scene frame f reads map f. Arguments after
// "--": pattern (soak's %04d form), first and last baked frame, material.
// Blender's image user shows file frame (f - frame_start + 1) + frame_offset.
const SOAK_PY_WETMAP = `
import bpy, sys
a = sys.argv[sys.argv.index("--") + 1:]
pattern, first, last, only = a[0], int(a[1]), int(a[2]), a[3]
nodes = [n for m in bpy.data.materials if m.node_tree is not None and (not only or m.name == only)
         for n in m.node_tree.nodes if n.bl_idname == "ShaderNodeTexImage" and n.get("soak_role") == "source"]
if not nodes:
    raise SystemExit("Soak: no material " + (repr(only) + " " if only else "") + "has a Soak Image wetness source")
img = bpy.data.images.load(pattern % first, check_existing=False)
img.source = "SEQUENCE"
img.colorspace_settings.name = "Non-Color"
for n in nodes:
    n.image = img
    n.image_user.frame_start = first
    n.image_user.frame_offset = first - 1
    n.image_user.frame_duration = last - first + 1
    n.image_user.use_auto_refresh = True
print("Soak: wet-map sequence", pattern, "on", len(nodes), "image source(s)")
bpy.context.scene.render.use_file_extension = True
`;

const SOAK_VIDEO_FORMATS = ["FFMPEG", "AVI_RAW", "AVI_JPEG"];

function compileJob(job) {
    print("Soak drying animation job submitted");
    const settings = job.settings;
    const format = soakText(settings, "format");
    if (format === "" || SOAK_VIDEO_FORMATS.indexOf(format) >= 0) {
        soakFail("format", `this job type renders image files, not "${format}"`);
    }
    const blendfile = soakText(settings, "blendfile");
    if (blendfile === "") soakFail("blendfile", "the blend file to render is required");
    const renderOutput = soakRenderOutputPath(job);
    settings.render_output_path = renderOutput;
    const renderDir = path.dirname(renderOutput);
    const wetPattern = path.join(renderDir, "wetmap", "wet.%04d.exr");

    const frames = soakJobFrames(settings.frames);
    const timing = {
        first: frames[0],
        time: soakNumber(settings, "time", 0, 1e9),
        frameTime: soakNumber(settings, "frame_time", 0, 1e6),
    };
    const mask = soakText(settings, "mask");
    let bakeArgs = ["bake", "drying"];
    if (mask !== "") bakeArgs.push(mask);
    bakeArgs = bakeArgs.concat(soakSizeSeedArgs(settings, mask === ""),
        ["--t-fill", String(soakNumber(settings, "t_fill", 0, 1)),
         "--noise", String(soakNumber(settings, "noise", 0, 1))],
        soakExtraArgs(settings, "extra_bake_args"));
    const bakes = soakAuthorBakeTasks(frames, soakChunks(settings.frames, settings, "bake_chunk_size"),
                                      bakeArgs, timing, wetPattern);

    const last = frames[frames.length - 1];
    const material = soakText(settings, "material");
    const renderTasks = [];
    for (const chunk of soakChunks(settings.frames, settings, "chunk_size")) {
        const task = author.Task(`render-${chunk}`, "blender");
        let args = ["--python-exit-code", "1", "--python-expr", SOAK_PY_WETMAP.trim()];
        if (settings.scene) args = args.concat(["--scene", String(settings.scene)]);
        args = args.concat([
            "--render-output", path.join(renderDir, path.basename(renderOutput)),
            "--render-format", format,
            "--render-frame", chunk.replace(/-/g, ".."), // Blender's frame range notation
            "--", wetPattern, String(frames[0]), String(last), material,
        ]);
        task.addCommand(author.Command("blender-render", {
            exe: "{blender}",
            exeArgs: "{blenderArgs}",
            argsBefore: [],
            blendfile: blendfile,
            args: args,
        }, frameCount(chunk)));
        // Flamenco's job.addTask() stores a copy: dependencies go in first.
        for (const b of bakes) {
            if (soakRunsOverlap(b.runs, soakChunkRuns(chunk))) task.addDependency(b.task);
        }
        renderTasks.push(task);
    }
    for (const b of bakes) job.addTask(b.task);
    for (const t of renderTasks) job.addTask(t);
}

// Whether a bake task's runs ({first, last}) share a frame with a chunk's runs ([first, last]).
function soakRunsOverlap(bakeRuns, renderRuns) {
    for (const a of bakeRuns) {
        for (const b of renderRuns) {
            if (a.first <= b[1] && b[0] <= a.last) return true;
        }
    }
    return false;
}

// Field replacement on the render output path, as simple_blender_render.js.
function soakRenderOutputPath(job) {
    const out = soakText(job.settings, "render_output_path");
    if (out === "") soakFail("render_output_path", "no render output path (set Render Output Root)");
    return out.replace(/{([^}]+)}/g, (match, group0) => {
        return group0 === "timestamp" ? formatTimestampLocal(job.created) : match;
    });
}

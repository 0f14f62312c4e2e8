/* The mesh formats Soak reads, one table for the check before the reader
 * starts (soak_mesh_format_ok) and --help (soak_mesh_formats_print), from
 * which tests/cli/meshes/formats_table.py writes the README's table
 * (tests/cli/mesh_formats.sh checks it is current). Every format is read
 * by Debian's Assimp 5.2 in the contained reader (mesh_contain.c); a format
 * is left out, with the reason, when the file holds no surface to bake,
 * names the files that do, or Assimp's reader fails on valid files. */
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "mesh_import.h"

typedef struct mesh_format {
    const char *ext, *name;
    const char *left_out; /* NULL: read; else why not */
} mesh_format;

static const mesh_format formats[] = {
    {"obj", "Wavefront OBJ (UTF-8, or UTF-16 with a byte-order mark)", NULL},
    {"ply", "Stanford PLY (ASCII and binary)", NULL},
    {"stl", "STL (ASCII and binary; STL holds no UVs)", NULL},
    {"off", "Object File Format", NULL},
    {"gltf", "glTF 2.0 and 1.0 (JSON)", NULL},
    {"glb", "glTF 2.0 and 1.0 binary", NULL},
    {"fbx", "Autodesk FBX (binary and ASCII)", NULL},
    {"dae", "Collada", NULL},
    {"zae", "Collada, zipped", NULL},
    {"3ds", "3D Studio mesh", NULL},
    {"blend", "Blender 2.5 to 3.0 (Assimp's reader; from newer Blender export FBX or glTF)", NULL},
    {"x", "DirectX (text and binary)", NULL},
    {"lwo", "LightWave object", NULL},
    {"lxo", "Modo object", NULL},
    {"ms3d", "MilkShape 3D", NULL},
    {"ase", "3ds Max ASCII export", NULL},
    {"ask", "3ds Max ASCII export (ASK)", NULL},
    {"ac", "AC3D", NULL},
    {"ac3d", "AC3D", NULL},
    {"acc", "AC3D", NULL},
    {"3mf", "3D Manufacturing Format", NULL},
    {"amf", "Additive Manufacturing Format", NULL},
    {"x3d", "X3D (XML)", NULL},
    {"x3db", "X3D binary", NULL},
    {"cob", "Caligari trueSpace", NULL},
    {"b3d", "Blitz3D", NULL},
    {"irrmesh", "Irrlicht mesh", NULL},
    {"irr", "Irrlicht scene", NULL},
    {"xml", "Ogre XML mesh, Irrlicht XML", NULL},
    {"md2", "Quake II model", NULL},
    {"md3", "Quake III model", NULL},
    {"md5mesh", "Doom 3 mesh", NULL},
    {"mdc", "Return to Castle Wolfenstein model", NULL},
    {"mdl", "Quake I / Half-Life model", NULL},
    {"hmp", "3D GameStudio terrain", NULL},
    {"smd", "Valve SMD", NULL},
    {"iqm", "Inter-Quake Model", NULL},
    {"nff", "Neutral File Format", NULL},
    {"enff", "Neutral File Format (extended)", NULL},
    {"raw", "PovRay raw triangles",
     "a format Assimp 5.2 reads badly: its reader crashes on RAW files with colours or textures"},
    {"ter", "Terragen terrain", NULL},
    {"q3o", "Quick3D object", NULL},
    {"q3s", "Quick3D scene", NULL},
    {"sib", "Silo", NULL},
    {"xgl", "XGL", NULL},
    {"zgl", "XGL, zipped", NULL},
    {"ogex", "Open Game Engine Exchange", NULL},
    {"dxf", "AutoCAD DXF (3DFACE entities)", NULL},
    {"ifc", "IFC (building models)", NULL},
    {"ifczip", "IFC, zipped", NULL},
    {"pmx", "MikuMikuDance", NULL},
    {"ndo", "Nendo", NULL},
    {"assbin", "Assimp binary dump", NULL},
    {"3d", "Unreal mesh (with its _a.3d and _d.3d)", NULL},
    {"lws", "LightWave scene", "a scene that names .lwo objects: bake the .lwo"},
    {"uc", "Unreal script", "a script that names the .3d files: bake the .3d"},
    {"bvh", "Biovision motion capture", "a skeleton's motion, no surface"},
    {"csm", "CharacterStudio motion capture", "a skeleton's motion, no surface"},
    {"md5anim", "Doom 3 animation", "an animation, no surface"},
    {"md5camera", "Doom 3 camera", "a camera path, no surface"},
    {"vta", "Valve vertex animation", "an animation, no surface"},
    {"mot", "LightWave motion", "an animation, no surface"},
    {"bsp", "Quake III level", "a level inside a .pk3 archive, not an asset"},
    {"pk3", "Quake III archive", "a game's level archive, not an asset"},
    {"max", "3ds Max scene", "3ds Max's own format, which no open reader reads: export FBX"},
    {"step", "STEP (CAD)", "CAD boundary representation, not a mesh: tessellate it (to OBJ or glTF) first"},
    {"stp", "STEP (CAD)", "CAD boundary representation, not a mesh: tessellate it (to OBJ or glTF) first"},
    {"jt", "JT (CAD)", "no reader in Assimp 5.2: export glTF or FBX"},
};

static const mesh_format *find(const char *path)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    if (!dot || (slash && dot < slash)) return NULL;
    for (size_t i = 0; i < sizeof formats / sizeof *formats; ++i)
        if (!strcasecmp(dot + 1, formats[i].ext)) return &formats[i];
    return NULL;
}

int soak_mesh_format_ok(const char *path, char *why, size_t whylen)
{
    const mesh_format *f = find(path);
    if (f && !f->left_out) return 1;
    if (!why || !whylen) return 0;
    if (f) snprintf(why, whylen, "%s: unsupported mesh format: .%s (%s) is %s", path, f->ext, f->name, f->left_out);
    else
        snprintf(why, whylen,
                 "%s: unsupported mesh format (the extension is not one of the mesh formats Soak "
                 "reads: `soak bake rain --help` lists them)",
                 path);
    return 0;
}

void soak_mesh_formats_print(FILE *out)
{
    fprintf(out, "mesh formats (Assimp in a contained reader; left out with the reason):\n");
    for (size_t i = 0; i < sizeof formats / sizeof *formats; ++i) {
        const mesh_format *f = &formats[i];
        fprintf(out, "  .%-9s %s%s%s\n", f->ext, f->name, f->left_out ? ": not read, " : "",
                f->left_out ? f->left_out : "");
    }
}

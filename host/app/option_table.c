/* Every command-line option, grouped by what it sets. The defaults quoted in
 * the help texts are the library's (vct/render.h, vct/voxels.h). */
#include <stddef.h>

#include "option_table.h"

#define GROUP(var, title, rows)                                                                    \
    const cli_option_group var = {title, rows, (int)(sizeof rows / sizeof rows[0])}

static const cli_option output_rows[] = {
    {"output", 'o', OPT_OUTPUT, 1, "FILE",
     "the image: .exr (linear, half floats, OpenEXR), .pfm (linear, 32-bit floats) or .png "
     "(exposure, tone curve and sRGB); render defaults to render.png"},
    {"aov", 0, OPT_AOV, 0, NULL,
     "also write arbitrary output values: cone tracing's direct, indirect, specular, ao, "
     "position, normal, albedo and indirect_variance; the other methods' albedo, normal, depth "
     "(and pt's direct and indirect light, and its variance with --denoise): layers of the same "
     "file for .exr, else "
     "FILE_albedo.pfm and so on beside it"},
    {"exr", 0, OPT_EXR, 1, "half|float",
     "EXR only: 16-bit half floats (default) or 32-bit floats, as PFM holds them"},
    {"stats", 0, OPT_STATS, 0, NULL, "per-stage device time, host time and memory"},
};
GROUP(cli_group_output, "output", output_rows);

static const cli_option denoise_rows[] = {
    {"denoise", 0, OPT_DENOISE, 0, NULL,
     "filter the image with the engine's denoiser, guided by the first hit's albedo, normal and "
     "depth and (pt) each pixel's variance; with --aov the noisy image and the guides are layers "
     "too; with several devices it runs on the first, after they have summed the frame (the "
     "viewer: one device, N toggles it). vct: its indirect light through all 5 passes "
     "(--indirect-filter)"},
};
GROUP(cli_group_denoise, "denoising (pt, pm, vct)", denoise_rows);

static const cli_option tone_rows[] = {
    {"exposure", 0, OPT_EXPOSURE, 1, "STOPS",
     "PNG and the viewer: scale by 2^STOPS (default: the image's log-average luminance to middle "
     "grey)"},
    {"tone", 0, OPT_TONE, 1, "filmic|clip",
     "PNG and the viewer: the tone curve after the exposure (default filmic, an ACES fit; clip: 1 "
     "and "
     "above is white)"},
};
GROUP(cli_group_tone, "tone mapping (PNG files and the viewer)", tone_rows);

static const cli_option device_rows[] = {
    {"device", 0, OPT_DEVICE, 1, "DEVICE",
     "the OpenCL device: an index or a name (`vct devices` lists them); for render and the "
     "viewer also several, one frame split across them: 0,2 | all | gpu | cpu (default "
     "$VCT_DEVICE, else the first GPU, else the first CPU)"},
};
GROUP(cli_group_device, "device", device_rows);

static const cli_option size_rows[] = {
    {"size", 0, OPT_SIZE, 2, "W H", "image size in pixels (default 512 512)"},
};
GROUP(cli_group_size, "image size", size_rows);

static const cli_option scene_rows[] = {
    {"camera-pos", 0, OPT_CAMERA_POS, 3, "X Y Z", "the camera's position"},
    {"look-at", 0, OPT_LOOK_AT, 3, "X Y Z", "the point the camera looks at"},
    {"up", 0, OPT_UP, 3, "X Y Z", "the camera's up vector"},
    {"fov", 0, OPT_FOV, 1, "DEGREES", "the vertical field of view, in (0, 179)"},
    {"point-light", 0, OPT_POINT_LIGHT, 6, "X Y Z R G B",
     "add a point light of radiant intensity RGB (W/sr) (repeatable, 16 at most)"},
    {"dir-light", 0, OPT_DIR_LIGHT, 6, "DX DY DZ R G B",
     "add a directional light of irradiance RGB travelling along D (repeatable)"},
    {"light-radius", 0, OPT_LIGHT_RADIUS, 1, "R",
     "every light's size, for soft shadows: world units for point and spot lights, radians for "
     "directional ones; 0 is hard"},
    {"ambient", 0, OPT_AMBIENT, 3, "R G B", "radiance arriving where rays leave the scene"},
};
GROUP(cli_group_scene, "scene overrides", scene_rows);

static const cli_option time_rows[] = {
    {"frame", 0, OPT_FRAME, 1, "N",
     "the scene as its first animation poses it at frame N (time N / --fps; default: the file's "
     "rest pose)"},
    {"frames", 0, OPT_FRAMES, 1, "A:B",
     "frames A to B, one image each: -o names them with a number pattern (out/shot_%04d.png)"},
    {"fps", 0, OPT_FPS, 1, "F", "frames per second of --frame and --frames (default 24)"},
    {"video", 0, OPT_VIDEO, 1, "FILE",
     "--frames: also encode the frames (PNG or EXR) into a video with ffmpeg, by FILE's ending "
     "(.mp4, .webm, .gif, ...), at --fps"},
    {"resume", 0, OPT_RESUME, 0, NULL,
     "--frames: render only the frames whose files are not there yet (files are written whole "
     "or not at all, so a sequence that was stopped goes on where it stopped)"},
};
GROUP(cli_group_time, "animation", time_rows);

static const cli_option accel_rows[] = {
    {"accel", 0, OPT_ACCEL, 1, "bvh|grid",
     "what rays traverse: the 4-wide BVH (default) or the uniform triangle grid"},
    {"bvh-build", 0, OPT_BVH_BUILD, 1, "clustered|linear",
     "the BVH's tree: agglomerative clustering (default, faster rays) or the linear hierarchy "
     "(faster build)"},
    {"bvh-levels", 0, OPT_BVH_LEVELS, 1, "auto|one|two",
     "one BVH over every triangle, or a BVH per mesh under one over the instances (holds a "
     "shared mesh once); auto (default): two where a mesh is placed more than once"},
    {"grid-res", 0, OPT_GRID_RES, CLI_ONE_OR_THREE, "N | NX NY NZ",
     "triangle grid cells per axis (default: from the triangle count)"},
};
GROUP(cli_group_accel, "acceleration structure", accel_rows);

static const cli_option method_rows[] = {
    {"method", 0, OPT_METHOD, 1, "METHOD",
     "vct (voxel cone tracing, the default), raycast (direct light, hard shadows), pt (path "
     "tracing, the reference), whitted (Whitted ray trees) or pm (progressive photon mapping); "
     "the viewer also takes voxels"},
};
GROUP(cli_group_method, "method", method_rows);

static const cli_option sampling_rows[] = {
    {"spp", 0, OPT_SPP, 1, "N", "pt: samples per pixel; pm: photon passes (default 64)"},
    {"time", 0, OPT_TIME, 1, "SECONDS",
     "pt and pm: render for this long instead of a sample count"},
    {"max-depth", 0, OPT_MAX_DEPTH, 1, "D",
     "pt and pm: path length (default 16); whitted: ray tree depth (default 8, at most 16)"},
    {"seed", 0, OPT_SEED, 1, "N", "pt and pm: the random sequence's seed (default 0)"},
};
GROUP(cli_group_sampling, "sampling (pt, pm)", sampling_rows);

static const cli_option vct_rows[] = {
    {"plan", 0, OPT_PLAN, 0, NULL, "print the effect plan: which passes this scene calls for"},
    {"effect", 0, OPT_EFFECT, 1, "NAME=on|off",
     "force an effect on or off against the plan: direct, shadows, indirect, specular, "
     "refraction, emission, ao, soft_shadows (repeatable)"},
    {"cones", 0, OPT_CONES, 1, "N",
     "the diffuse gather at the camera's hits: 9 N rays, N 1 to 16 (default 9)"},
    {"cone-step", 0, OPT_CONE_STEP, 1, "F",
     "cone march step as a fraction of the cone's diameter (default 1)"},
    {"cone-offset", 0, OPT_CONE_OFFSET, 1, "VOXELS",
     "how far cones start off their surface, in voxels (default 4)"},
    {"cone-levels", 0, OPT_CONE_LEVELS, 1, "blend|nearest",
     "a sample blends two octree levels (default) or reads the nearest one"},
    {"dense-diffuse", 0, OPT_DENSE_DIFFUSE, 0, NULL,
     "the diffuse gather at every pixel (by default at every other pixel per axis, the rest filled "
     "in from traced neighbours on the same surface)"},
    {"indirect-filter", 0, OPT_INDIRECT_FILTER, 1, "N",
     "the indirect diffuse light through N passes of the denoiser, guided by the first hit's "
     "albedo, normal and depth and by the variance of its gather rays, and the direct light's "
     "emitter samples through up to 3 (default 3; 0: none; --denoise: 5)"},
    {"edge-samples", 0, OPT_EDGE_SAMPLES, 1, "N",
     "N x N camera rays at pixels on an edge (surface, material, hard shadow), shown as their "
     "mean; 2N x 2N where the shading on its two sides is four times apart, 4N x 4N on an "
     "emitter's border (default 4; 1: pixel centres only)"},
    {"ao-distance", 0, OPT_AO_DISTANCE, 1, "F",
     "ambient occlusion's reach as a fraction of the voxel volume (default 0.125)"},
    {"bounces", 0, OPT_BOUNCES, 1, "N",
     "light bounces gathered in the voxels, 1 to 4 (default 4), then the rest of the series at "
     "the scene's bounce ratio, per colour channel"},
    {"exact-bounces", 0, OPT_EXACT_BOUNCES, 0, NULL, "no rest of the series after the last bounce"},
    {"dense-bounces", 0, OPT_DENSE_BOUNCES, 0, NULL,
     "every voxel gathers each bounce (by default a quarter of them do, the others take the mean "
     "of "
     "their neighbours on the same surface)"},
    {"light-carry", 0, OPT_LIGHT_CARRY, 0, NULL,
     "--frames: where lights or objects move, carry the voxels' light over from the frame "
     "before (what moved voxelized alone, direct light kept where nothing moved reaches, one "
     "bounce a frame, settling over a few frames) instead of building the voxels and gathering "
     "every bounce again"},
    {"emitters", 0, OPT_EMITTERS, 1, "rays|cones",
     "emissive triangles as lights sampled with shadow rays (default), or seen through the "
     "voxels' cones alone"},
    {"copy-voxels", 0, OPT_COPY_VOXELS, 0, NULL,
     "several devices: the first builds the voxels, the others copy them (default: each builds "
     "its own)"},
};
GROUP(cli_group_vct, "voxel cone tracing (--method vct)", vct_rows);

static const cli_option voxel_rows[] = {
    {"voxel-res", 0, OPT_VOXEL_RES, 1, "N",
     "voxels per axis, a power of two up to 1024 (default 128 for render, 256 for voxelize)"},
    {"thin", 0, OPT_THIN, 0, NULL, "6-separating voxels (default: conservative)"},
    {"voxel-bounds", 0, OPT_VOXEL_BOUNDS, 4, "X Y Z SIZE",
     "the voxel cube's corner and side (default: around the scene)"},
    {"bricks", 0, OPT_BRICKS, 1, "auto|buffer|image",
     "the brick pool's storage (default auto: 3D images on GPUs)"},
    {"anisotropic", 0, OPT_ANISOTROPIC, 0, NULL,
     "six directional radiance values per brick sample"},
    {"isotropic", 0, OPT_ISOTROPIC, 0, NULL, "one radiance per brick sample (the default)"},
};
GROUP(cli_group_voxels, "voxels", voxel_rows);

static const cli_option whitted_rows[] = {
    {"subsample", 0, OPT_SUBSAMPLE, 1, "N",
     "whitted and raycast: rays at the corners of N x N squares (a power of two), squares "
     "whose corners agree interpolated, the others split (default 0: off)"},
    {"no-guard", 0, OPT_NO_GUARD, 0, NULL,
     "subsampling also interpolates squares that a piece of the mesh smaller than the square "
     "touches"},
    {"contrast", 0, OPT_CONTRAST, 1, "C",
     "subsampling: corners whose radiance spreads by more than C of their mean disagree too "
     "(default 0.05; 0: the corners' keys alone)"},
};
GROUP(cli_group_whitted, "adaptive subsampling (whitted, raycast)", whitted_rows);

static const cli_option pm_rows[] = {
    {"photons", 0, OPT_PHOTONS, 1, "N", "photons per pass (default 131072)"},
    {"pm-radius", 0, OPT_PM_RADIUS, 1, "R",
     "initial gather radius (default 1.5 % of the scene's size)"},
    {"pm-caustic-radius", 0, OPT_PM_CAUSTIC_RADIUS, 1, "R",
     "initial caustic gather radius (default as --pm-radius; with --pm-fixed, half of it)"},
    {"pm-alpha", 0, OPT_PM_ALPHA, 1, "A", "radius reduction per pass, in (0, 1] (default 2/3)"},
    {"pm-fixed", 0, OPT_PM_FIXED, 0, NULL, "fixed radii instead of progressive ones"},
    {"final-gather", 0, OPT_FINAL_GATHER, 1, "N",
     "read the global map at the hits of N rays per pixel and pass"},
    {"pm-direct-photons", 0, OPT_PM_DIRECT_PHOTONS, 0, NULL,
     "direct light from photons too (no shadow rays)"},
    {"pm-kernel", 0, OPT_PM_KERNEL, 1, "box|epanechnikov",
     "the density estimate's kernel (default epanechnikov)"},
    {"pm-normal-filter", 0, OPT_PM_NORMAL_FILTER, 1, "C|off",
     "photons whose normal's cosine with the surface's is below C are not counted (default 0: "
     "those facing away)"},
};
GROUP(cli_group_pm, "photon mapping (--method pm)", pm_rows);

static const cli_option compare_rows[] = {
    {"error-image", 0, OPT_ERROR_IMAGE, 1, "FILE.png",
     "write the mean absolute error per pixel, blue (none) to red"},
    {"error-scale", 0, OPT_ERROR_SCALE, 1, "E",
     "the error that maps to red (default: the largest)"},
};
GROUP(cli_group_compare, "error image", compare_rows);

static const cli_option view_rows[] = {
    {"capture", 0, OPT_CAPTURE, 1, "FILE.png",
     "render one frame, read the window back into FILE.png and exit"},
    {"keys", 0, OPT_KEYS, 1, "K,K,...",
     "keys pressed before the first frame (1, F1, [, left, r, ...), and size=WxH to resize the "
     "window"},
    {"display", 0, OPT_DISPLAY, 1, "auto|interop|host",
     "how frames reach OpenGL: CL-GL interop where the device shares with GL (auto, the "
     "default), interop only, or through the host"},
};
GROUP(cli_group_view, "viewer", view_rows);

#include "app/cli/cli.h"
#include "app/measure/cli_ref.h"

#include <stdio.h>
#include <string.h>

static void usage(FILE *f)
{
    fprintf(f,
            "tessera: a bathroom and interior-design planner\n"
            "\n"
            "usage:\n"
            "  tessera demo [--output DIR] [--size WxH] [--supersample N] [--backend B]\n"
            "      renders the shipped demo bathroom from each of its cameras into out/\n"
            "  tessera render PROJECT -o OUT [--camera NAME] [--size WxH] [--supersample N]\n"
            "                [--backend egl|osmesa]\n"
            "      renders a project file to PNG, JPEG, TIFF (8-bit sRGB) or EXR (linear)\n"
            "      (any size, tiled beyond the GL limits; --shadows off|hard|soft, --dpi N,\n"
            "      --all-views -o DIR: every stored camera)\n"
            "  tessera panorama PROJECT -o OUT.jpg [--camera NAME] [--size 4096x2048]\n"
            "                [--faces DIR]\n"
            "      a 360-degree equirectangular panorama (GPano XMP) from six cube faces\n"
            "  tessera video PROJECT -o OUT.mp4 [--seconds S] [--fps N] [--size WxH]\n"
            "      a smooth path through the stored cameras: PNG frames, MP4 with ffmpeg\n"
            "  tessera bench PROJECT [--size WxH] [--frames N] [--warmup N] [--camera NAME]\n"
            "                [--backend egl|osmesa] [--csv FILE]\n"
            "      milliseconds per frame (median and spread) against a full-screen floor\n"
            "      (--probes every-frame|once|on-change|time-sliced, --blur prefiltered|box-mips)\n"
            "      (--animate OBJECT: drag it 10 mm a frame; the cpu row: CPU ms, all threads)\n"
            "  render, demo and bench take --quality draft|interactive|final|print\n"
            "  tessera probe-bench [--size WxH] [--frames N] [--csv FILE]\n"
            "      what reflection probes cost: per update by resolution, per object\n"
            "  tessera reference PROJECT -o OUT.exr [--camera NAME] [--size WxH] [--samples N]\n"
            "      the ground truth: a CPU ray tracer (Embree) with the same shading\n"
            "  tessera compare A B [--mask M] [--heatmap OUT.png] [--worst N]\n"
            "      RMSE and PSNR in linear RGB, over all pixels and the masked ones, and where\n"
            "      the error is (the N blocks that carry most of it)\n"
            "  tessera sweep PROJECT [--size WxH] [--samples N] [--csv FILE] [--plot FILE.png]\n"
            "      the speed/accuracy trade: each reflection setting timed and compared\n"
            "  tessera extremes [--size WxH] [--samples N] [--markdown FILE]\n"
            "      RENDERING.md section 11: every extreme finite on the GPU and in the reference\n"
            "  tessera catalog search|show|import|export|info|bench|model|thumbs|lod ... (--help)\n"
            "  tessera edit PROJECT SCRIPT [-o OUT]\n"
            "      replays an edit script (place, move, tile, undo, ...; docs/editing.md)\n"
            "  tessera check PROJECT [--barrier-free | --wheelchair]\n"
            "      collisions and clearances of the fixtures (exit 1 on errors)\n"
            "  tessera print PROJECT -o OUT.pdf [--paper A4|A3] [--landscape] [--scale 1:20|fit]\n"
            "                [--svg DIR] [--renders DIR|none]  (tessera print --help)\n"
            "  tessera share PROJECT -o DIR [--size WxH] [--panorama-size WxH]\n"
            "      a folder for any browser: renders, plan, 360-degree panorama, part list\n"
            "      the print set: plan, wall elevations with tiles, renders, part list\n"
            "  tessera quantities PROJECT [--csv] [--surplus PCT] [--offcuts] [--bench N]\n"
            "      the tile part list (whole/cut tiles, offcuts, boxes) and bill of materials\n"
            "  tessera surfaces PROJECT [--csv]\n"
            "      the room's tileable surfaces: frames, holes (openings, covered) and net m2\n"
            "  tessera export-glb PROJECT [-o OUT.glb]\n"
            "      the whole project (room, tiles, objects, products) as GLB for other tools\n"
            "\n"
            "The OpenGL backend is EGL (Mesa surfaceless) unless --backend or TESSERA_GL says\n"
            "otherwise; OSMesa is the fallback.\n");
}

int app_cli_main(int argc, char **argv)
{
    if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") ||
        !strcmp(argv[1], "help")) {
        usage(argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    if (!strcmp(argv[1], "render"))
        return app_cli_render(argc, argv);
    if (!strcmp(argv[1], "panorama"))
        return app_cli_panorama(argc, argv);
    if (!strcmp(argv[1], "video"))
        return app_cli_video(argc, argv);
    if (!strcmp(argv[1], "demo"))
        return app_cli_demo(argc, argv);
    if (!strcmp(argv[1], "bench"))
        return app_cli_bench(argc, argv);
    if (!strcmp(argv[1], "probe-bench"))
        return app_cli_probe_bench(argc, argv);
    if (!strcmp(argv[1], "reference"))
        return app_cli_reference(argc, argv);
    if (!strcmp(argv[1], "compare"))
        return app_cli_compare(argc, argv);
    if (!strcmp(argv[1], "sweep"))
        return app_cli_sweep(argc, argv);
    if (!strcmp(argv[1], "extremes"))
        return app_cli_extremes(argc, argv);
    if (!strcmp(argv[1], "catalog"))
        return app_cli_catalog(argc, argv);
    if (!strcmp(argv[1], "edit"))
        return app_cli_edit(argc, argv);
    if (!strcmp(argv[1], "check"))
        return app_cli_check(argc, argv);
    if (!strcmp(argv[1], "print"))
        return app_cli_print(argc, argv);
    if (!strcmp(argv[1], "quantities"))
        return app_cli_quantities(argc, argv);
    if (!strcmp(argv[1], "surfaces"))
        return app_cli_surfaces(argc, argv);
    if (!strcmp(argv[1], "export-glb"))
        return app_cli_export_glb(argc, argv);
    if (!strcmp(argv[1], "share"))
        return app_cli_share(argc, argv);
    if (!strcmp(argv[1], "--version")) {
        printf("tessera 0.1.0\n");
        return 0;
    }
    fprintf(stderr, "tessera: unknown command \"%s\" (try tessera --help)\n", argv[1]);
    return 2;
}

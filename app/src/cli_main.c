#include "app/cli.h"
#include "app/cli_ref.h"

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
            "  tessera bench PROJECT [--size WxH] [--frames N] [--warmup N] [--camera NAME]\n"
            "                [--backend egl|osmesa] [--csv FILE]\n"
            "      milliseconds per frame (median and spread) against a full-screen floor\n"
            "      (--probes every-frame|once|on-change|time-sliced, --blur prefiltered|box-mips)\n"
            "  render, demo and bench take --quality draft|interactive|final|print\n"
            "  tessera probe-bench [--size WxH] [--frames N] [--csv FILE]\n"
            "      what reflection probes cost: per update by resolution, per object\n"
            "  tessera reference PROJECT -o OUT.exr [--camera NAME] [--size WxH] [--samples N]\n"
            "      the ground truth: a CPU ray tracer (Embree) with the same shading\n"
            "  tessera compare A B [--mask M] [--heatmap OUT.png]\n"
            "      RMSE and PSNR in linear RGB, over all pixels and the masked ones\n"
            "  tessera sweep PROJECT [--size WxH] [--samples N] [--csv FILE] [--plot FILE.png]\n"
            "      the speed/accuracy trade: each reflection setting timed and compared\n"
            "  tessera extremes [--size WxH] [--samples N] [--markdown FILE]\n"
            "      RENDERING.md section 11: every extreme finite on the GPU and in the reference\n"
            "  tessera catalog search|show|import|export|info|bench ... (tessera catalog --help)\n"
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
    if (!strcmp(argv[1], "--version")) {
        printf("tessera 0.1.0\n");
        return 0;
    }
    fprintf(stderr, "tessera: unknown command \"%s\" (try tessera --help)\n", argv[1]);
    return 2;
}

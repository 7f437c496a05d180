/* UI scripts: a file of actions the planner runs one after the other, as a user would, so a
 * test (and a measurement) can drive the window under Xvfb. One action per line; blank lines
 * and lines starting with # are skipped:
 *   wait N                 let N frames pass
 *   orbit DX DY            drag the orbit view by DX, DY pixels (repeats over `frames`)
 *   zoom STEPS             wheel steps, positive = closer
 *   mode orbit|walk        the 3D navigation mode
 *   walk FORWARD RIGHT     walk (mm); walls stop the walker
 *   camera NAME            jump to a stored viewpoint
 *   quality NAME           draft, interactive, final, print
 *   screenshot FILE.png    the whole window, panels included
 *   search TEXT...         type into the catalog browser's search field (the rest of the line)
 *   select N               pick the N-th hit (from 1) of the catalog browser
 *   expect-hits N          fail unless the catalog browser shows at least N hits
 *   fly NAME SECONDS       a smooth flight to a stored viewpoint
 *   present on|off         presentation mode: the UI hidden
 *   tour on|off            the automatic tour through the viewpoints
 *   turntable on|off       turn the view about its target
 *   print-shot FILE        a print-quality screenshot (twice the window size)
 *   view 3d|plan           the 3D view or the 2D plan
 *   edit LINE...           one edit line (docs/editing.md), as the UI's own buttons send them
 *   place-selected X Y     place the catalog browser's selected product at a plan point
 *   drag NAME X Y          drag a fixture's footprint centre to a plan point and let go
 *                          (NAME "-": the selected fixture, e.g. the one just placed)
 *   move-wall W OFFSET     drag wall W of the plan OFFSET mm outward (negative: inward)
 *   drag3d NAME X Y        the same as a hand drags it in the 3D view: moved live over the
 *                          action's frames (frames N), one move edit on the last
 *   tile-selected SURFACE  tile a surface with the catalog browser's selected tile
 *   undo / redo            Ctrl+Z / Ctrl+Y
 *   save FILE              save as FILE (atomic); "save -" saves to the project's own file
 *   expect-objects N       fail unless the project has exactly N objects
 *   expect-added N         fail unless N objects were added since the window opened
 *   share DIR              the share export of the document as it is now, as a job (below);
 *                          the script waits for it, the window keeps drawing
 *   drop-selected plan|3d SX SY  drag the browser's selected product to window pixel SX SY
 *                          of the plan or the 3D view and let go (with `frames N` the ghost
 *                          travels there first); placed and snapped as place-selected
 *   drag-selected plan|3d SX SY  the same drag, still held at SX SY (the ghost shows; a
 *                          screenshot can catch it); the next drop-selected lets go
 *   expect-total MIN MAX   fail unless the quantities panel's gross total is in [MIN, MAX]
 *   new                    a new project (the empty room), unsaved changes discarded
 *   open FILE              open a project file (a bad one fails the script, the message says why)
 *   save-as FILE           save under a new name; the document's file is FILE from then on
 *   view elevation         the wall elevation of the tile panel's surface (tiles.h)
 *   elevation-wall N       show wall N (from 0) in the tile panel and the elevation view
 *   tile-surface SURFACE   show a surface ("floor", "wall:1", "prewall:NAME:front", ...)
 *   tile-pattern SURFACE PATTERN   straight, half-offset, third-offset, vertical-stack,
 *                          diagonal or herringbone (SURFACE: a surface or a tiling's name)
 *   tile-grout SURFACE WIDTH_MM [R G B]   joint width and colour (linear RGB 0-1)
 *   tile-start SURFACE X Y | SURFACE centred|corner   where the tile grid starts
 *   tile-rotate SURFACE DEG
 *   tile-band SURFACE FROM TO      the heights a wall tiling covers (TO 0: to the ceiling)
 *   tile-border SURFACE BOTTOM_MM  a border row of the browser's selected tile
 *   elevation-click S T    click the elevation view at surface point S T (mm): the start
 *   expect-pattern SURFACE PATTERN fail unless the tiling on SURFACE has that pattern
 *   expect-tiles SURFACE N fail unless its layout has at least N tiles
 *   tile-panel on|off      the tile panel over the 3D view too (it shows in the elevation)
 *   expect-probe MATERIAL UPDATE  fail unless the material's probe updates so (every-frame,
 *                          once, on-change, time-sliced, static, default; docs/editing.md)
 *   wait-file PATH         hold the script until PATH exists and the input sent before it
 *                          was handled, the window taking live input meanwhile (the pointer
 *                          chooses the active pane): an outside driver (xdotool in the input
 *                          tests) works the window, then creates PATH; 60 s with neither the
 *                          file nor any input fail the script
 *   locate widget LABEL... log where a button or text field labelled LABEL is, in window
 *                          pixels, and whether its panel shows it (input_script.c)
 *   locate widget-if-drawn LABEL...  the same, logging "not drawn" instead of failing
 *   locate fixture NAME... log where a fixture's centre is in the plan view (view plan first)
 *   locate box NAME        log a fixture's footprint in plan mm: centre, half sides, turn,
 *                          underside and top (what the walker and the checks see)
 *   locate eye             log the view's eye in plan mm and the camera mode (walk|orbit)
 *   locate selection       log the window-pixel box around the selection's outline in the
 *                          3D view (selection_3d.c), or that none shows
 *   locate handle NAME     log where the selection's move-x, move-y or rotate handle in the 3D
 *                          view is grabbed and where a drag of it goes: 500 mm along an arrow,
 *                          52 degrees round the ring (handles_3d.c)
 *   locate plan X Y        log where plan point X Y (mm) shows in the plan view
 *   pick NAME              select a fixture by its object's name, as a click on it in the
 *                          plan or the 3D view does ("-": clear the selection)
 *   expect-search TEXT...  fail unless the catalog browser's search field holds exactly TEXT
 *   panes both|one         plan and 3D side by side, or the active view alone (View menu)
 *   split SX               drag the splitter between the panes to window x SX
 *   print-pdf FILE.pdf     start a job (planner_actions.h) and go on at once: the print set
 *   render-image FILE      the window's view at print quality, twice the window's size
 *   export-glb FILE.glb    the project as GLB
 *   panorama FILE.jpg      a 360-degree panorama from the window's view
 *   video FILE.mp4         the video of the viewpoints
 *   job-wait               wait for the running job; fail unless it succeeded
 *   job-cancel             cancel the running job, wait for it to stop; fail unless cancelled
 *   autosave-now           autosave now (the window does every 30 s while there are changes)
 *   expect-recovery yes|no fail unless the recovery offer is (not) showing
 *   recover yes|no         answer the recovery offer
 *   expect-read-only yes|no fail unless another window has the project (save refused)
 *   expect-save-refused    save over the project; fail unless the save is refused
 *   expect-recent FILE     fail unless FILE is the newest of the recent files
 *   open-recent N          open the N-th recent file (from 1)
 *   dialog open|save-as|print-pdf|export-glb  the native file dialog; the script waits until
 *                          it is answered (a person, or xdotool in a test), then acts on it
 *   wait-bake              hold the script until the baked light is up to date: no bake
 *                          settling or running and the crossfade to the new light done
 *                          (at once when the bake is off)
 *   wait-warmup            hold the script until the shader warm-up's renders are done
 *                          (shader_warmup.c; at once when TESSERA_SHADER_WARMUP=off)
 *   bake-hold on|off       keep edits' bakes from starting (on) until off: a test sees the
 *                          light carried over from before the edit, refined, then the new
 *   quit                   close the window (exit 0)
 * Any action may be followed by `frames N` to spread it over N frames (orbit, zoom, walk). */
#ifndef UI_SCRIPT_H
#define UI_SCRIPT_H

#include <stddef.h>

typedef enum ui_action_kind {
    UI_ACT_WAIT,
    UI_ACT_ORBIT,
    UI_ACT_ZOOM,
    UI_ACT_MODE,
    UI_ACT_WALK,
    UI_ACT_CAMERA,
    UI_ACT_QUALITY,
    UI_ACT_SCREENSHOT,
    UI_ACT_SEARCH,
    UI_ACT_SELECT,
    UI_ACT_EXPECT_HITS,
    UI_ACT_FLY,
    UI_ACT_PRESENT,
    UI_ACT_TOUR,
    UI_ACT_TURNTABLE,
    UI_ACT_PRINT_SHOT,
    UI_ACT_VIEW,
    UI_ACT_EDIT,
    UI_ACT_PLACE_SELECTED,
    UI_ACT_DRAG,
    UI_ACT_UNDO,
    UI_ACT_REDO,
    UI_ACT_SAVE,
    UI_ACT_EXPECT_OBJECTS,
    UI_ACT_EXPECT_ADDED,
    UI_ACT_TILE_SELECTED,
    UI_ACT_SHARE,
    UI_ACT_DROP_SELECTED, /* drag and drop, quantities, files */
    UI_ACT_DRAG_SELECTED,
    UI_ACT_EXPECT_TOTAL,
    UI_ACT_NEW,
    UI_ACT_OPEN,
    UI_ACT_SAVE_AS,
    UI_ACT_EXPECT_PROBE,   /* probe_props.h */
    UI_ACT_ELEVATION_WALL, /* the tile panel and the elevation view (tiles.h) */
    UI_ACT_TILE_SURFACE,
    UI_ACT_TILE_PATTERN,
    UI_ACT_TILE_GROUT,
    UI_ACT_TILE_START,
    UI_ACT_TILE_ROTATE,
    UI_ACT_TILE_BAND,
    UI_ACT_TILE_BORDER,
    UI_ACT_ELEVATION_CLICK,
    UI_ACT_EXPECT_PATTERN,
    UI_ACT_EXPECT_TILES,
    UI_ACT_TILE_PANEL,
    UI_ACT_DRAG3D,
    UI_ACT_MOVE_WALL,
    UI_ACT_WAIT_FILE, /* driving the window with outside input (input_script.c) */
    UI_ACT_LOCATE,
    UI_ACT_EXPECT_SEARCH,
    UI_ACT_PANES, /* the window's layout (panel_layout.h) */
    UI_ACT_SPLIT,
    UI_ACT_PICK,        /* the selection, by name */
    UI_ACT_FILES,       /* planner_actions.h: text is "VERB ARGUMENT" */
    UI_ACT_WAIT_BAKE,   /* planner_bake.c */
    UI_ACT_WAIT_WARMUP, /* shader_warmup.c */
    UI_ACT_WAIT_STILL,  /* planner_live.c: the still view at its preset */
    UI_ACT_BAKE_HOLD,
    UI_ACT_QUIT
} ui_action_kind;

typedef struct ui_action {
    ui_action_kind kind;
    double a, b;    /* numbers of the action */
    int frames;     /* frames the action is spread over (>= 1) */
    char text[512]; /* file, name or mode */
    int line;       /* in the script, for messages */
} ui_action;

typedef struct ui_script {
    ui_action *actions;
    int count;
} ui_script;

/* Reads and checks the whole script first, so a typo on line 30 is reported before the
 * window opens. 0 on success; else err holds "FILE:LINE: problem". */
int ui_script_read(const char *path, ui_script *out, char *err, size_t err_size);
/* tile_script.c: checks the words of a tile action (tile-pattern ...) as the script is read;
 * 1 ok, else 0 and why. */
int ui_tile_action_check(ui_action_kind kind, const char *text, char *why, size_t why_size);
void ui_script_free(ui_script *s);

#endif

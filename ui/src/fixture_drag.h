/* Dragging a placed fixture in the 3D view: press on it, move the pointer, let go. While the
 * button is held the fixture's objects are moved in the document and in the built scene
 * (app_scene_move_object: no rebuild, only the probes that see it are captured again, within
 * the frame's face budget), so the drag runs at the view's frame rate; on release they go back
 * to where they were and one `move` edit (snapped to the nearest wall, as the plan's drag)
 * makes the move one undo step. */
#ifndef UI_FIXTURE_DRAG_H
#define UI_FIXTURE_DRAG_H

typedef struct ui_fixture_drag {
    int active;
    int by_pointer;         /* started by the mouse (which then ends it), not by a script */
    int object;             /* the fixture's first project object */
    double plane_z;         /* the drag's horizontal plane: the height grabbed, mm */
    double grab[2];         /* the plan point grabbed on that plane, mm */
    double start_centre[2]; /* the fixture's centre when grabbed, mm */
    double centre[2];       /* where it is now, mm */
    int *objects;           /* the project objects moved (the fixture's group) and their */
    double (*start)[3];     /* document positions when grabbed, mm */
    int object_count;
} ui_fixture_drag;

#endif

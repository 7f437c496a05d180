#ifndef APP_DESIGN_FAR_OBJECTS_H
#define APP_DESIGN_FAR_OBJECTS_H

#include "app/design/placement.h"

/* How far a fixture may reach outside the room's box before it is a finding, mm. */
#define APP_FAR_OBJECT_LIMIT_MM 1000.0

/* Appends an error finding (kind outside-room) for every fixture whose box lies more than
 * APP_FAR_OBJECT_LIMIT_MM outside the room's box (the plan's bounding box from the floor to
 * the plan's height), naming the fixture, the distance and the side ("above the ceiling",
 * "below the floor", "beside the walls"). Such an object is a unit slip (mm typed as m), and
 * the renderer's depth range stops short of it (docs/rendering.md, "Depth range"). */
app_result app_far_objects_check(const app_project *p, const app_fixture *fx, int count,
                                 app_findings *out, char *err, size_t err_size);

#endif

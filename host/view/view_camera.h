/* The viewer's fly camera: yaw and pitch about the scene's up axis, moved
 * along its own axes. Pure arithmetic, no window. */
#ifndef VCT_VIEW_CAMERA_H
#define VCT_VIEW_CAMERA_H

#include "vct/vct.h"

typedef struct view_camera {
    vct_camera start; /* the scene's camera, given back exactly until moved */
    float position[3];
    float up[3], ahead[3], side[3]; /* world frame: up, and the start's heading */
    float yaw, pitch;               /* radians from the start's heading */
    float speed;                    /* world units per second */
    int moved;
} view_camera;

/* Starts at the scene's camera; speed: a quarter of the scene's extent per second. */
void view_camera_init(view_camera *c, const vct_camera *start, float extent);
/* Mouse look: dx, dy in pixels (right, down). */
void view_camera_look(view_camera *c, float dx, float dy);
/* Movement along (forward, right, up), each -1..1, for dt seconds. */
void view_camera_move(view_camera *c, float forward, float right, float up, float dt);
/* Scroll: each notch scales the speed by 1.25. */
void view_camera_scroll(view_camera *c, float notches);
void view_camera_get(const view_camera *c, vct_camera *out);

#endif

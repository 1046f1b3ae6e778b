/*
 * scene/scene.h - `onbstudy scene` (scene.c): the methods ranked on a mesh's own normals.
 * src/scene/ holds the command and its speed source (speed.h); the meshes
 * come from src/mesh/.
 */
#ifndef ONB_SCENE_H
#define ONB_SCENE_H

int cmd_scene(int argc, char **argv);

#endif

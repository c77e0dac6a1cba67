#pragma once
// The strokes of a spatial task: task/strokes.h takes either kind of task.
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/strokes.h>

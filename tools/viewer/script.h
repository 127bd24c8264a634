/* SPDX-License-Identifier: MIT */
/* Scripted input (`sinew view --script FILE`): the viewer runs the
 * file's commands one after the other from its main loop, drawing between
 * frames as it does interactively, so a test (or a figure) can drive it
 * without a mouse. One command per line, split into words as control files
 * are (cli/words.h): spaces or tabs between words, a name with spaces in
 * double quotes, `#` starts a comment.
 *
 *   model MODEL             load a built-in model or a model file
 *   variant NAME|N          rebuild the model in that variant
 *   weight KG               rebuild it with that weight choice
 *   level N                 rebuild it at that level (0 .. 4)
 *   scene NAME              load an engine scene of scenes/registry.h (`sinew scene --help`)
 *   play N                  step N frames, drawing after each
 *   activation NAME A       activation A (0 .. 1) of a muscle or group
 *   tension NAME N          tension target N (newtons) of a muscle or group
 *   pulse NAME              activation 1 for the next frame only
 *   recruit DELTA           recruit DELTA more (or fewer) neurons of the worm's motor pool
 *   solver NAME             the engine's solver: baumgarte, ngs, soft_step
 *   overlay NAME on|off     contacts, normals, impulses, aabbs, joints, reactions, sleeping
 *   angles                  print "angles t=T NAME=DEG ..." with the model's hinge angles on stdout
 *   status                  print "status t=T frame=N playing=0|1 dragging=0|1 scale=PX_PER_M
 *                           centre=X,Y canvas=X,Y,W,H recruited=N ..." (the canvas's place in the
 *                           window; recruited -1 without a motor pool), then the model's build
 *                           options and command or the scene's name, the solver settings and
 *                           the target="NAME", and message="TEXT" while the window shows an error
 *   locate NAME             print "locate NAME X Y": where a model's part, or the middle of a
 *                           control (as `set` names it), is in the window, px
 *   set CONTROL VALUE       set a control of the panels as a user would (its handlers run):
 *                           model, scene, variant, weight ("5 kg"), muscle: an item's text;
 *                           level, activation, tension, solver iterations, substeps: a number;
 *                           tension-mode, play, warm-starting and the overlays: on|off;
 *                           reload, step, export-activation, export-tension,
 *                           export-selected_forces, export-contraction: clicked (any VALUE)
 *   print TEXT              print TEXT on stdout
 *   wait-for FILE           wait until FILE exists, then let the window handle its input: an
 *                           input tool (xdotool) acts meanwhile and creates FILE when done
 *   screenshot FILE         write the window as a PNG
 *   visible                 check that every control and graph is drawn whole, or can be
 *                           scrolled to with a scrollbar shown (layout_check.h); print
 *                           "visible WIDTHxHEIGHT: N widgets", or fail naming the first cut one
 *   export GRAPH FILE       write a graph's CSV (activation, tension, selected_forces, contraction)
 *   quit                    close the viewer
 *
 * A failing command prints "FILE:LINE: what went wrong" on stderr and
 * ends the viewer with status 1: a number out of its range (a control's
 * too, or a fraction where it takes whole numbers) is an error, as on the
 * command line, never clamped; a model or scene that a command or a
 * control (model, reload, ...) loads and that fails fails at that line.
 * A script that cannot be read (a folder) fails before the window opens.
 */
#ifndef VIEWER_SCRIPT_H
#define VIEWER_SCRIPT_H

#include <stdbool.h>
#include <stddef.h>

#include "viewer.h"

typedef struct script script;

/* Reads and splits the whole file (an error names the file and line);
 * NULL on failure, with `error` set. */
script *script_load(const char *path, char *error, size_t error_size);
void script_free(script *commands);

/* Runs the commands from the main loop, starting once the window is shown. */
void script_start(script *commands, viewer *app);

#endif

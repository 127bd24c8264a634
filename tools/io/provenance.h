/* SPDX-License-Identifier: MIT */
/* Which version and which settings made a file: every CSV file the tools
 * write (`sinew run`, `sinew scene`, `sinew experiment`, the viewer's
 * graph exports) gets a sidecar, and every figure (chart/chart.h) carries
 * the version and the command line inside it.
 *
 * Why a sidecar, and not a comment line or extra columns: the CSV must
 * stay what pandas.read_csv and R's read.csv read with their defaults
 * (header on line 1, a rectangle of numbers). A leading "# ..." line
 * becomes the header of both; columns of text repeated on every row
 * would turn numeric tables into mixed ones. The sidecar follows the
 * naming of the W3C "CSV on the Web" recommendation (Tabular Metadata,
 * 2015, §5.2): FILE.csv's metadata is FILE.csv-metadata.json, found
 * beside it, read with any JSON reader (json.load, jsonlite::read_json):
 *
 *   {
 *     "@context": "http://www.w3.org/ns/csvw",
 *     "url": "arm.csv",                  the CSV it describes, beside it
 *     "dc:creator": "sinew 0.2.0",
 *     "sinew": {
 *       "version": "0.2.0",
 *       "command": ["sinew", "run", "arm", "--duration", "1"],
 *       "settings": { ... }              what the command made the data with
 *     }
 *   }
 *
 * "sinew" is not a CSVW term (a CSVW validator warns that it ignores it).
 * The settings are those the writer names (model, variant, weight, frame
 * rate, solver settings, ...); the command holds everything else given.
 * Nothing in the sidecar changes from one run to the next (no date, no
 * absolute path of the program), so rerunning a command rewrites the
 * same bytes.
 *
 * The sidecar is written whole or not at all, like the CSV
 * (io/atomic_file.h), after it.
 */
#ifndef IO_PROVENANCE_H
#define IO_PROVENANCE_H

#include <jansson.h>
#include <stdbool.h>
#include <stddef.h>

#include "mu/model.h"
#include "rb/world.h"
#include "scenes/registry.h"

/* Remembers the program's command line for every file written after;
 * main() calls it first. argv must live as long as the program (main's
 * does); argv[0] is kept as its base name, "sinew" or "sinew-view".
 * Before a call, files name no command. */
void provenance_set_command_line(int argc, char *const *argv);

/* "sinew VERSION", the creator named in every file. */
const char *provenance_creator(void);

/* The command line as one line of text that a POSIX shell reads back: an
 * argument that is empty or holds a space or a character the shell would
 * interpret is in single quotes ("sinew plot 'my data.csv'"); "" when none
 * was set. Truncated to `size`. */
void provenance_command_text(char *text, size_t size);

/* The settings of a muscle model as built: "model" (its name), "variant"
 * (index and name), "weight_kg" (or null without a weight), "level",
 * "weld_glues", "frame_rate_hz", "substeps_per_frame", "gravity_m_s2" and
 * "solver" (every field of rb_solver_settings, "type" by name). NULL when
 * out of memory. */
json_t *provenance_model_settings(mu_model *model, const mu_model_options *options);

/* The settings of an engine scene as built: "scene" (its name),
 * "parameters" (each of its parameters by name, a seed as a decimal
 * string, since a JSON number read as a double keeps only 53 bits),
 * "gravity_m_s2" and "solver". NULL when out of memory. */
json_t *provenance_scene_settings(const scene_instance *scene);

/* Writes CSV_PATH-metadata.json for the CSV file `csv_path`, with
 * `settings` (a JSON object, or NULL for none), which it takes over. On
 * failure `error` names the file. */
bool provenance_write_sidecar(const char *csv_path, json_t *settings, char *error, size_t error_size);

#endif

/* SPDX-License-Identifier: MIT */
/* Broad phase by sort and sweep (Baraff 1992) over fat boxes.
 *
 * Each step, every shape's box is enlarged by how far the shape may
 * travel relative to its neighbours during the step (its swept box), so
 * every pair that could touch by the end of the step reaches the narrow
 * phase and gets a speculative contact. A fat box is a swept box grown by
 * RB_FAT_MARGIN and kept while the swept box stays inside it (the fat
 * boxes of Box2D's dynamic tree, Catto 2019). The pairs are the shapes
 * that may collide (rb_should_collide) and whose fat boxes overlap; each
 * is a contact, whose narrow phase runs while the swept boxes overlap
 * (contact.c).
 *
 * The pairs change only where fat boxes change:
 *   - nothing left its fat box (a pile at rest): nothing is searched and
 *     the contacts stay as they are;
 *   - a few shapes left theirs (a ball falling past a resting pile, a box
 *     knocked off a stack): only they are searched around, by a range in
 *     the sorted sweep, O(log n + neighbours in x) each. A pair begins
 *     where the new fat boxes overlap and the old ones did not, and ends
 *     the other way round: the list of pairs that begin and the list of
 *     those that end are all the contacts are told (v3's move buffer, where
 *     the old boxes stand in for Box2D's set of pairs);
 *   - shapes came or went, which shapes may collide changed
 *     (candidates_stale), or more than one shape in REQUERY_LIMIT left its
 *     box: every fat box is made anew and all pairs are found by sweeps,
 *     one per band in y, each box meeting only the boxes of its band that
 *     start before it ends: O(n + overlaps in x within a band), the shapes
 *     kept sorted by the lower x of their fat boxes from one step to the
 *     next.
 * Every list of pairs is put in (body, shape) order, so the contacts, and
 * every run, meet the pairs in the same order. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "allocator.h"
#include "broad_phase.h"
#include "error.h"

static int compare_sweep_entries(const void *a, const void *b)
{
    const struct rb_sweep_entry *p = a;
    const struct rb_sweep_entry *q = b;
    if (p->box.lower.x != q->box.lower.x) {
        return p->box.lower.x < q->box.lower.x ? -1 : 1;
    }
    return (p->shape > q->shape) - (p->shape < q->shape);
}

static int compare_pairs(const void *a, const void *b)
{
    const rb_pair *p = a;
    const rb_pair *q = b;
    if (p->body_key != q->body_key) {
        return p->body_key < q->body_key ? -1 : 1;
    }
    return (p->shape_key > q->shape_key) - (p->shape_key < q->shape_key);
}

bool rb_should_collide(const rb_world *world, int shape_a, int shape_b)
{
    const rb_shape *a = &world->shapes[shape_a];
    const rb_shape *b = &world->shapes[shape_b];
    if (a->body == b->body || (a->sensor && b->sensor)) {
        return false;
    }
    if (world->bodies[a->body].type != RB_BODY_DYNAMIC && world->bodies[b->body].type != RB_BODY_DYNAMIC) {
        return false;
    }
    bool filters_agree = a->filter.group_index != 0 && a->filter.group_index == b->filter.group_index
                             ? a->filter.group_index > 0
                             : (a->filter.category_bits & b->filter.mask_bits) != 0 &&
                                   (b->filter.category_bits & a->filter.mask_bits) != 0;
    /* The filters first: they are a few bit operations, where the joints
     * take a walk along a body's joint list. */
    return filters_agree && !rb_joints_forbid_collision(world, a->body, b->body);
}

/* The shape's box at the start of the step, grown by the speculative
 * distance and by the farthest its surface can move in dt: |v|·dt for
 * the centre plus |ω|·dt·extent for the rotation about it. */
static rb_aabb swept_aabb(const rb_world *world, int index, double dt, double speculative_distance)
{
    const rb_shape *shape = &world->shapes[index];
    const rb_body_state *state = &world->states[shape->body];
    double travel = dt * (rb_length(state->linear_velocity) + fabs(state->angular_velocity) * shape->extent);
    double margin = speculative_distance + travel;
    rb_aabb box = rb_shape_tight_aabb(world, index);
    box.lower = rb_sub(box.lower, rb_v2(margin, margin));
    box.upper = rb_add(box.upper, rb_v2(margin, margin));
    return box;
}

/* The pair of two shapes, the one of the lower body first. */
static rb_pair make_pair(const rb_world *world, int shape_a, int shape_b)
{
    int body_a = world->shapes[shape_a].body;
    int body_b = world->shapes[shape_b].body;
    if (body_a > body_b || (body_a == body_b && shape_a > shape_b)) {
        int t = shape_a;
        shape_a = shape_b;
        shape_b = t;
        t = body_a;
        body_a = body_b;
        body_b = t;
    }
    return (rb_pair){
        .body_key = ((uint64_t)(uint32_t)body_a << 32) | (uint32_t)body_b,
        .shape_key = ((uint64_t)(uint32_t)shape_a << 32) | (uint32_t)shape_b,
        .shape_a = shape_a,
        .shape_b = shape_b,
    };
}

/* Appends the pair of two shapes to a list of pairs. */
static rb_status push_pair(const rb_world *world, rb_pair **list, int *count, int *capacity, int shape_a, int shape_b)
{
    if (rb_grow_array((void **)list, capacity, *count + 1, sizeof **list) != 0) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_world_step: out of memory for shape pairs");
    }
    (*list)[(*count)++] = make_pair(world, shape_a, shape_b);
    return RB_OK;
}

/* Swaps two elements eight bytes at a time, then byte by byte: every
 * element sorted here (a sweep entry, a refit, a pair) is a multiple of
 * eight bytes, which a swap byte by byte took some 160 instructions to
 * move, most of a heapsort's time. */
static void swap_bytes(unsigned char *a, unsigned char *b, size_t size)
{
    size_t i = 0;
    for (; i + sizeof(uint64_t) <= size; i += sizeof(uint64_t)) {
        uint64_t s;
        uint64_t t;
        memcpy(&s, a + i, sizeof s);
        memcpy(&t, b + i, sizeof t);
        memcpy(a + i, &t, sizeof t);
        memcpy(b + i, &s, sizeof s);
    }
    for (; i < size; ++i) {
        unsigned char t = a[i];
        a[i] = b[i];
        b[i] = t;
    }
}

typedef int compare_fn(const void *, const void *);

/* Sifts element `root` down the max-heap of the first `end` elements. */
static void sift_down(unsigned char *a, int root, int end, size_t size, compare_fn *compare)
{
    for (int child = 2 * root + 1; child < end; child = 2 * root + 1) {
        if (child + 1 < end && compare(a + (size_t)child * size, a + (size_t)(child + 1) * size) < 0) {
            ++child;
        }
        if (compare(a + (size_t)root * size, a + (size_t)child * size) >= 0) {
            return;
        }
        swap_bytes(a + (size_t)root * size, a + (size_t)child * size, size);
        root = child;
    }
}

/* Heapsort (Williams 1964) of `count` elements of `size` bytes whose
 * keys all differ, so the order is the same on every run. Where qsort
 * may take memory from the C library (glibc's merge sort does past a
 * kilobyte), this takes none: a step allocates nothing. O(n log n). */
static void heap_sort(void *base, int count, size_t size, compare_fn *compare)
{
    unsigned char *a = base;
    for (int i = count / 2 - 1; i >= 0; --i) {
        sift_down(a, i, count, size, compare);
    }
    for (int end = count - 1; end > 0; --end) {
        swap_bytes(a, a + (size_t)end * size, size); /* the largest goes behind the heap */
        sift_down(a, 0, end, size, compare);
    }
}

/* Insertion sort by (lower x, shape index): from one refresh to the next
 * the boxes barely move, so the last order is nearly sorted and this
 * takes O(n) (a full sort would take O(n log n) every time). When the
 * order has changed a lot (a scene blowing apart, many teleports) the
 * insertions would cost up to O(n²): past SORT_SHIFTS_PER_ENTRY shifts
 * an entry on average, a heapsort finishes the job. Either way the order is
 * the same, as no two entries compare equal. */
#define SORT_SHIFTS_PER_ENTRY 8

static void sort_sweep(struct rb_sweep_entry *sweep, int count)
{
    long shifts_left = (long)SORT_SHIFTS_PER_ENTRY * count;
    for (int i = 1; i < count; ++i) {
        struct rb_sweep_entry entry = sweep[i];
        int j = i;
        while (j > 0 && compare_sweep_entries(&sweep[j - 1], &entry) > 0) {
            sweep[j] = sweep[j - 1];
            --j;
            --shifts_left;
        }
        sweep[j] = entry;
        if (shifts_left < 0) {
            heap_sort(sweep, count, sizeof *sweep, compare_sweep_entries);
            return;
        }
    }
}

/* Sorts world->pairs by (body_key, shape_key) in O(pairs + bodies): a counting sort by the lower body, whose runs (a
 * body's pairs with the bodies above it, a handful) are then put in order by insertion. A comparison sort took a sixth
 * of a pyramid's step. */
static rb_status sort_pairs(rb_world *world)
{
    int count = world->pair_count;
    int bodies = world->body_slots;
    if (count < 2) {
        return RB_OK;
    }
    if (rb_grow_array((void **)&world->sorted_pairs, &world->sorted_pair_capacity, count,
                      sizeof *world->sorted_pairs) != 0 ||
        rb_grow_array((void **)&world->pair_bucket, &world->pair_bucket_capacity, bodies + 1,
                      sizeof *world->pair_bucket) != 0) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_world_step: out of memory for shape pairs");
    }
    int *start = world->pair_bucket;
    for (int b = 0; b <= bodies; ++b) {
        start[b] = 0;
    }
    for (int i = 0; i < count; ++i) {
        start[(world->pairs[i].body_key >> 32) + 1] += 1;
    }
    for (int b = 0; b < bodies; ++b) {
        start[b + 1] += start[b];
    }
    rb_pair *sorted = world->sorted_pairs;
    for (int i = 0; i < count; ++i) {
        sorted[start[world->pairs[i].body_key >> 32]++] = world->pairs[i];
    }
    /* start[b] is now the end of body b's run: sort each run. */
    int run_begin = 0;
    for (int b = 0; b < bodies; ++b) {
        for (int i = run_begin + 1; i < start[b]; ++i) {
            rb_pair pair = sorted[i];
            int j = i;
            while (j > run_begin && compare_pairs(&sorted[j - 1], &pair) > 0) {
                sorted[j] = sorted[j - 1];
                --j;
            }
            sorted[j] = pair;
        }
        run_begin = start[b];
    }
    world->sorted_pairs = world->pairs;
    world->pairs = sorted;
    int capacity = world->sorted_pair_capacity;
    world->sorted_pair_capacity = world->pair_capacity;
    world->pair_capacity = capacity;
    return RB_OK;
}

/* Puts every live shape in the sweep, after shapes were created or
 * destroyed. */
static rb_status rebuild_sweep(rb_world *world)
{
    if (rb_grow_array((void **)&world->sweep, &world->sweep_capacity, world->shape_count, sizeof *world->sweep) != 0) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_world_step: out of memory for the broad phase");
    }
    int rebuilt = 0;
    for (int i = 0; i < world->shape_slots; ++i) {
        if (world->shapes[i].in_use && world->solid_shape_count > 0) {
            world->sweep[rebuilt++].shape = i;
        }
    }
    world->sweep_count = rebuilt;
    world->sweep_stale = false;
    return RB_OK;
}

static bool contains(rb_aabb outer, rb_aabb inner)
{
    return outer.lower.x <= inner.lower.x && outer.lower.y <= inner.lower.y && inner.upper.x <= outer.upper.x &&
           inner.upper.y <= outer.upper.y;
}

static rb_aabb fat_box_around(rb_aabb box)
{
    rb_vec2 margin = rb_v2(RB_FAT_MARGIN, RB_FAT_MARGIN);
    return (rb_aabb){rb_sub(box.lower, margin), rb_add(box.upper, margin)};
}

static bool overlaps_in_y(const rb_aabb *a, const rb_aabb *b)
{
    return a->lower.y <= b->upper.y && b->lower.y <= a->upper.y;
}

/* The sweep cut into horizontal bands for a full search. One sweep in x
 * meets, for each box, every box that overlaps it in x: in a scene laid
 * out in two dimensions, a whole column. The 100 × 100 joint grid made a
 * hundred tests per box, and its pairs phase took 2.2 ms of a 15 ms step;
 * in bands it takes 1.2 ms. Within a band of the height of the tallest
 * dynamic box, a box meets only its own row's neighbours. A box is put in
 * every band it reaches, at most two for a dynamic one; a pair is
 * reported only in the band where the overlap of the two boxes in y
 * begins, which both reach, so once. */
typedef struct band_layout {
    double bottom;         /* m, the lowest fat box's lower y */
    double inverse_height; /* 1/m, bands per metre */
    int count;             /* >= 1 */
} band_layout;

/* Bands no lower than the tallest dynamic fat box (so a dynamic box
 * reaches at most two), tiling [bottom, top], at most one per entry; one
 * band when the range is empty or not finite. */
static band_layout layout_bands(double bottom, double top, double tallest, int entries)
{
    band_layout bands = {.bottom = bottom, .inverse_height = 0.0, .count = 1};
    double range = top - bottom;
    if (isfinite(range) && range > 0.0 && tallest > 0.0) {
        double count = fmin(floor(range / tallest), (double)entries);
        if (count > 1.0) {
            bands.count = (int)count;
            bands.inverse_height = count / range;
        }
    }
    return bands;
}

static int band_of(const band_layout *bands, double y)
{
    double index = (y - bands->bottom) * bands->inverse_height;
    if (!(index > 0.0)) { /* below, or not a number */
        return 0;
    }
    return index < (double)(bands->count - 1) ? (int)index : bands->count - 1;
}

/* Copies the sweep's entries into world->band_entries, band after band,
 * each band in the sweep's order of lower x; band b's entries end at
 * world->band_end[b]. The arrays are kept large enough for every entry to
 * reach one band more than it does now, and for as many bands as entries:
 * a moving scene's boxes cross band edges from step to step, and without
 * that room the array would grow in whichever step first has a few more
 * boxes across an edge than any step before. */
static rb_status fill_bands(rb_world *world, const band_layout *bands)
{
    if (rb_grow_array((void **)&world->band_end, &world->band_end_capacity,
                      (bands->count > world->sweep_count ? bands->count : world->sweep_count) + 1,
                      sizeof *world->band_end) != 0) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_world_step: out of memory for the broad phase");
    }
    int *cursor = world->band_end;
    for (int b = 0; b <= bands->count; ++b) {
        cursor[b] = 0;
    }
    const struct rb_sweep_entry *sweep = world->sweep;
    for (int k = 0; k < world->sweep_count; ++k) {
        for (int b = band_of(bands, sweep[k].box.lower.y); b <= band_of(bands, sweep[k].box.upper.y); ++b) {
            cursor[b + 1] += 1;
        }
    }
    for (int b = 0; b < bands->count; ++b) {
        cursor[b + 1] += cursor[b];
    }
    if (rb_grow_array((void **)&world->band_entries, &world->band_entry_capacity,
                      cursor[bands->count] + world->sweep_count, sizeof *world->band_entries) != 0) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_world_step: out of memory for the broad phase");
    }
    for (int k = 0; k < world->sweep_count; ++k) {
        for (int b = band_of(bands, sweep[k].box.lower.y); b <= band_of(bands, sweep[k].box.upper.y); ++b) {
            world->band_entries[cursor[b]++] = sweep[k];
        }
    }
    return RB_OK; /* cursor[b] has moved to the end of band b */
}

/* The pairs within band b: a sweep in x over its entries. */
static rb_status sweep_band(rb_world *world, const band_layout *bands, int b, const struct rb_sweep_entry *entries,
                            int count)
{
    for (int i = 0; i < count; ++i) {
        rb_aabb box_a = entries[i].box;
        for (int j = i + 1; j < count && entries[j].box.lower.x <= box_a.upper.x; ++j) {
            const rb_aabb *box_b = &entries[j].box;
            if (!overlaps_in_y(&box_a, box_b) || band_of(bands, rb_max(box_a.lower.y, box_b->lower.y)) != b) {
                continue;
            }
            if (rb_should_collide(world, entries[i].shape, entries[j].shape)) {
                RB_TRY(push_pair(world, &world->pairs, &world->pair_count, &world->pair_capacity, entries[i].shape,
                                 entries[j].shape));
            }
        }
    }
    return RB_OK;
}

static double box_width(const rb_aabb *box) { return box->upper.x - box->lower.x; }

/* A search around one shape scans the sweep from the widest box's width
 * before it, so a ground 200 m across would make every search scan 200 m
 * of the sweep. Boxes much wider than any dynamic one (over twice the
 * widest) are listed apart and met one by one; up to WIDE_SHAPE_LIMIT of
 * them, else none is. */
#define WIDE_SHAPE_LIMIT 16

static rb_status list_wide_shapes(rb_world *world)
{
    double limit = 2.0 * (world->widest_dynamic_box + 2.0 * RB_FAT_MARGIN);
    int wide = 0;
    double max_width = 0.0;
    double narrow_max_width = 0.0;
    for (int k = 0; k < world->sweep_count; ++k) {
        double width = box_width(&world->sweep[k].box);
        max_width = rb_max(max_width, width);
        if (width > limit) {
            ++wide;
        } else {
            narrow_max_width = rb_max(narrow_max_width, width);
        }
    }
    world->wide_shape_count = 0;
    if (wide > WIDE_SHAPE_LIMIT) {
        world->wide_box_limit = INFINITY;
        world->sweep_max_width = max_width;
        return RB_OK;
    }
    if (rb_grow_array((void **)&world->wide_shapes, &world->wide_shape_capacity, wide, sizeof *world->wide_shapes) !=
        0) {
        return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_world_step: out of memory for the broad phase");
    }
    for (int k = 0; k < world->sweep_count; ++k) {
        if (box_width(&world->sweep[k].box) > limit) {
            world->wide_shapes[world->wide_shape_count++] = world->sweep[k].shape;
        }
    }
    world->wide_box_limit = limit;
    world->sweep_max_width = narrow_max_width;
    return RB_OK;
}

/* New fat boxes around the swept ones, sorted, and every pair of shapes
 * that may collide and whose fat boxes overlap. */
static rb_status find_all_pairs(rb_world *world)
{
    int count = world->sweep_count;
    double bottom = INFINITY;
    double top = -INFINITY;
    for (int k = 0; k < count; ++k) {
        rb_shape *shape = &world->shapes[world->sweep[k].shape];
        shape->fat_aabb = fat_box_around(shape->aabb);
        world->sweep[k].box = shape->fat_aabb;
        bottom = rb_min(bottom, shape->fat_aabb.lower.y);
        top = rb_max(top, shape->fat_aabb.upper.y);
    }
    sort_sweep(world->sweep, count);
    RB_TRY(list_wide_shapes(world));

    band_layout bands = layout_bands(bottom, top, world->tallest_dynamic_box + 2.0 * RB_FAT_MARGIN, count);
    RB_TRY(fill_bands(world, &bands));
    world->pair_count = 0;
    int begin = 0;
    for (int b = 0; b < bands.count; ++b) {
        int end = world->band_end[b];
        /* An empty band has nothing to sweep, and its entries may not even
         * be allocated (no shape in the sweep: band_entries is NULL, and
         * NULL + 0 is undefined). */
        if (end > begin) {
            RB_TRY(sweep_band(world, &bands, b, world->band_entries + begin, end - begin));
        }
        begin = end;
    }
    return sort_pairs(world);
}

/* The first entry of the sorted sweep that is not before (lower_x,
 * shape), by bisection; `count` when all are. */
static int first_entry_not_before(const struct rb_sweep_entry *sweep, int count, double lower_x, int shape)
{
    int first = 0;
    int last = count;
    while (first < last) {
        int middle = first + (last - first) / 2;
        const struct rb_sweep_entry *entry = &sweep[middle];
        bool before = entry->box.lower.x < lower_x || (entry->box.lower.x == lower_x && entry->shape < shape);
        if (before) {
            first = middle + 1;
        } else {
            last = middle;
        }
    }
    return first;
}

/* Finds a moved shape's entry in the sweep by its old key and gives it
 * the new fat box, carrying the entry along to where its new key
 * belongs; false if the entry is not where its old key says (the sweep no
 * longer mirrors the fat boxes: sweep them all instead). The sweep stays
 * sorted by its entries' keys throughout, so the next moved shape's entry
 * is found by bisection too. O(log n + entries passed). */
static bool move_entry(rb_world *world, const struct rb_refit *refit)
{
    struct rb_sweep_entry *sweep = world->sweep;
    int count = world->sweep_count;
    int k = first_entry_not_before(sweep, count, refit->old_box.lower.x, refit->shape);
    if (k == count || sweep[k].shape != refit->shape) {
        return false;
    }
    struct rb_sweep_entry entry = {.box = world->shapes[refit->shape].fat_aabb, .shape = refit->shape};
    while (k > 0 && compare_sweep_entries(&sweep[k - 1], &entry) > 0) {
        sweep[k] = sweep[k - 1];
        --k;
    }
    while (k + 1 < count && compare_sweep_entries(&sweep[k + 1], &entry) < 0) {
        sweep[k] = sweep[k + 1];
        ++k;
    }
    sweep[k] = entry;
    world->sweep_max_width = rb_max(world->sweep_max_width, box_width(&entry.box));
    return true;
}

/* Whether the pair of `shape` and `other` begins or ends as `shape`'s
 * fat box goes from `old_box` to `box` and `other`'s from `other_old` to
 * `other_box`: listed in new_pairs or ended_pairs if so. */
static rb_status compare_boxes(rb_world *world, int shape, rb_aabb old_box, rb_aabb box, int other, rb_aabb other_old,
                               rb_aabb other_box)
{
    ++world->statistics.broad_phase_box_tests;
    bool before = rb_aabb_overlaps(old_box, other_old);
    bool now = rb_aabb_overlaps(box, other_box);
    if (before == now || !rb_should_collide(world, shape, other)) {
        return RB_OK;
    }
    return now ? push_pair(world, &world->new_pairs, &world->new_pair_count, &world->new_pair_capacity, shape, other)
               : push_pair(world, &world->ended_pairs, &world->ended_pair_count, &world->ended_pair_capacity, shape,
                           other);
}

/* The pairs of the moved shapes that begin or end: each moved shape
 * meets the entries whose lower x lies within the widest box before the
 * span of its old and new boxes, every box that overlaps either in x, and
 * the wide shapes. A pair whose other shape moved too is looked at from
 * the shape of lower index, and only for a beginning: two shapes that
 * both moved may end far apart, out of each other's span (see
 * find_pairs_ended_between_moved). */
static rb_status find_pairs_around_moved(rb_world *world)
{
    const rb_shape *shapes = world->shapes;
    const struct rb_sweep_entry *sweep = world->sweep;
    int count = world->sweep_count;
    for (int r = 0; r < world->refit_count; ++r) {
        int shape = world->refits[r].shape;
        rb_aabb old_box = world->refits[r].old_box;
        rb_aabb box = shapes[shape].fat_aabb;
        rb_aabb span = {rb_v2(rb_min(old_box.lower.x, box.lower.x), rb_min(old_box.lower.y, box.lower.y)),
                        rb_v2(rb_max(old_box.upper.x, box.upper.x), rb_max(old_box.upper.y, box.upper.y))};
        int k = first_entry_not_before(sweep, count, span.lower.x - world->sweep_max_width, -1);
        for (; k < count && sweep[k].box.lower.x <= span.upper.x; ++k) {
            const rb_aabb other_box = sweep[k].box;
            if (!rb_aabb_overlaps(span, other_box)) { /* a whole column of a pile overlaps in x */
                continue;
            }
            int other = sweep[k].shape;
            int other_slot = shapes[other].refit_slot;
            if (other == shape || box_width(&other_box) > world->wide_box_limit || (other_slot > 0 && other < shape)) {
                continue;
            }
            if (other_slot == 0) {
                RB_TRY(compare_boxes(world, shape, old_box, box, other, other_box, other_box));
            } else if (rb_aabb_overlaps(box, other_box)) {
                RB_TRY(
                    compare_boxes(world, shape, old_box, box, other, world->refits[other_slot - 1].old_box, other_box));
            }
        }
        for (int w = 0; w < world->wide_shape_count; ++w) {
            int wide = world->wide_shapes[w];
            RB_TRY(compare_boxes(world, shape, old_box, box, wide, shapes[wide].fat_aabb, shapes[wide].fat_aabb));
        }
    }
    return RB_OK;
}

static int compare_old_lower_x(const void *a, const void *b)
{
    const struct rb_refit *p = a;
    const struct rb_refit *q = b;
    if (p->old_box.lower.x != q->old_box.lower.x) {
        return p->old_box.lower.x < q->old_box.lower.x ? -1 : 1;
    }
    return (p->shape > q->shape) - (p->shape < q->shape);
}

/* The pairs of two moved shapes whose old fat boxes overlapped and whose
 * new ones do not: a sweep in x over the old boxes of the moved shapes
 * alone. Reorders world->refits. */
static rb_status find_pairs_ended_between_moved(rb_world *world)
{
    struct rb_refit *refits = world->refits;
    int count = world->refit_count;
    heap_sort(refits, count, sizeof *refits, compare_old_lower_x);
    for (int i = 0; i < count; ++i) {
        for (int j = i + 1; j < count && refits[j].old_box.lower.x <= refits[i].old_box.upper.x; ++j) {
            if (!overlaps_in_y(&refits[i].old_box, &refits[j].old_box)) {
                continue;
            }
            int a = refits[i].shape;
            int b = refits[j].shape;
            RB_TRY(compare_boxes(world, a, refits[i].old_box, world->shapes[a].fat_aabb, b, refits[j].old_box,
                                 world->shapes[b].fat_aabb));
        }
    }
    return RB_OK;
}

/* Tells the pairs that begin and end as the moved shapes' fat boxes
 * change, each list sorted as the contacts are; *done is false if the
 * sweep must be searched whole instead (a wide box moved, or a box grew
 * wide: the list of wide shapes would change). */
static rb_status requery_moved(rb_world *world, bool *done)
{
    *done = false;
    rb_shape *shapes = world->shapes;
    for (int r = 0; r < world->refit_count; ++r) {
        const struct rb_refit *refit = &world->refits[r];
        if (box_width(&refit->old_box) > world->wide_box_limit ||
            box_width(&shapes[refit->shape].fat_aabb) > world->wide_box_limit) {
            return RB_OK;
        }
    }
    for (int r = 0; r < world->refit_count; ++r) {
        if (!move_entry(world, &world->refits[r])) {
            return RB_OK;
        }
    }
    for (int r = 0; r < world->refit_count; ++r) {
        shapes[world->refits[r].shape].refit_slot = r + 1;
    }
    rb_status status = find_pairs_around_moved(world);
    for (int r = 0; r < world->refit_count; ++r) {
        shapes[world->refits[r].shape].refit_slot = 0;
    }
    RB_TRY(status);
    RB_TRY(find_pairs_ended_between_moved(world));
    heap_sort(world->new_pairs, world->new_pair_count, sizeof *world->new_pairs, compare_pairs);
    heap_sort(world->ended_pairs, world->ended_pair_count, sizeof *world->ended_pairs, compare_pairs);
    *done = true;
    return RB_OK;
}

/* Whether a body stands still until something wakes it or places it:
 * static, or asleep, and without velocity (a body can be made asleep and
 * moving). Its shapes' swept boxes then stay what they were, whatever dt. */
static bool stands_still(const rb_world *world, int body)
{
    const rb_body_state *state = &world->states[body];
    bool still = world->bodies[body].type == RB_BODY_STATIC || !world->bodies[body].awake;
    return still && state->linear_velocity.x == 0.0 && state->linear_velocity.y == 0.0 &&
           state->angular_velocity == 0.0;
}

/* Each shape's swept box for this step, and the tallest and widest of
 * those of dynamic bodies (they only shape the bands of a full search);
 * the shapes whose swept box left their fat box get a new fat box and are
 * listed in world->refits with their old one. Unless `every_shape`, the
 * shapes of bodies that stand still are passed over: their boxes were
 * made at rest (a body put to sleep, or placed, makes world->boxes_stale)
 * and would come out the same, so a pile asleep costs nothing here. */
static void sweep_boxes_forward(rb_world *world, double dt, bool every_shape)
{
    double speculative_distance = RB_SPECULATIVE_SLOPS * world->settings.linear_slop;
    struct rb_refit *refits = world->refits;
    int refit_count = 0;
    int boxes = 0;
    double tallest = 0.0;
    double widest = 0.0;
    /* In index order rather than the sweep's: the shapes and their bodies
     * are then read one after another from memory instead of at random. */
    for (int index = 0; index < world->shape_slots; ++index) {
        rb_shape *shape = &world->shapes[index];
        if (!shape->in_use || (!every_shape && stands_still(world, shape->body))) {
            continue;
        }
        shape->aabb = swept_aabb(world, index, dt, speculative_distance);
        ++boxes;
        if (world->bodies[shape->body].type == RB_BODY_DYNAMIC) {
            tallest = rb_max(tallest, shape->aabb.upper.y - shape->aabb.lower.y);
            widest = rb_max(widest, box_width(&shape->aabb));
        }
        if (!contains(shape->fat_aabb, shape->aabb)) {
            refits[refit_count++] = (struct rb_refit){.shape = index, .old_box = shape->fat_aabb};
            shape->fat_aabb = fat_box_around(shape->aabb);
        }
    }
    world->refit_count = refit_count;
    world->statistics.broad_phase_boxes = boxes;
    world->tallest_dynamic_box = tallest;
    world->widest_dynamic_box = widest;
}

/* Past one shape in REQUERY_LIMIT leaving its fat box in a step, one
 * sweep over all the shapes is cheaper than a search for each. */
#define REQUERY_LIMIT 8

rb_status rb_broad_phase_update_pairs(rb_world *world, double dt)
{
    rb_statistics *statistics = &world->statistics;
    statistics->broad_phase_moved = 0;
    statistics->broad_phase_box_tests = 0;
    statistics->broad_phase_boxes = 0;
    world->pairs_rebuilt = false;
    world->new_pair_count = 0;
    world->ended_pair_count = 0;
    bool search_all = world->sweep_stale || world->candidates_stale;
    if (world->sweep_stale) {
        RB_TRY(rebuild_sweep(world));
    }
    /* Two sensors never pair, so while every shape is a sensor (the
     * musculoskeletal models' bones) no pair can exist: the sweep stays
     * empty and the step spends nothing here. */
    if (world->sweep_count > 0) {
        if (rb_grow_array((void **)&world->refits, &world->refit_capacity, world->shape_count, sizeof *world->refits) !=
            0) {
            return rb_report_error(RB_ERR_OUT_OF_MEMORY, "rb_world_step: out of memory for the broad phase");
        }
        sweep_boxes_forward(world, dt, search_all || world->boxes_stale);
        world->boxes_stale = false;
        search_all = search_all || world->refit_count > world->sweep_count / REQUERY_LIMIT;
    }
    if (!search_all && world->refit_count > 0) {
        world->candidates_stale = true; /* until the lists are complete (out of memory midway) */
        bool done = false;
        RB_TRY(requery_moved(world, &done));
        if (done) {
            world->candidates_stale = false;
            statistics->broad_phase_moved = world->refit_count;
            ++statistics->broad_phase_requeries;
        } else {
            search_all = true;
            world->new_pair_count = 0;
            world->ended_pair_count = 0;
            statistics->broad_phase_box_tests = 0;
        }
    }
    if (search_all) {
        world->candidates_stale = true;
        RB_TRY(find_all_pairs(world));
        world->candidates_stale = false;
        world->pairs_rebuilt = true;
        statistics->broad_phase_moved = world->sweep_count;
        ++statistics->broad_phase_sweeps;
    }
    return RB_OK;
}

/* Sort and sweep keeps the boxes of the last step's start, grown for
 * that step's motion; bodies placed or stepped since may have left them,
 * and shapes created since are not in the sweep. They cannot bound a
 * query, so this is a pass over the shapes with their boxes as they are
 * now: O(n) box tests, a few nanoseconds per shape. A tree of fat boxes
 * kept around every shape would answer in O(log n + found). */
void rb_broad_phase_query(const rb_world *world, rb_aabb box, rb_broad_phase_visit_fn *visit, void *context)
{
    for (int i = 0; i < world->shape_slots; ++i) {
        if (world->shapes[i].in_use && rb_aabb_overlaps(rb_shape_tight_aabb(world, i), box) &&
            !visit(world, i, context)) {
            return;
        }
    }
}

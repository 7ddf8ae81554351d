/**
 * Every numerical tolerance of the engine, in one place, each with its reason.
 * Tolerances are relative to the scale of the quantity they compare unless the name says otherwise.
 * Nothing else in the engine may introduce a bare epsilon.
 */

/** Unit round-off of IEEE-754 double precision (2^-53). The base of every other tolerance. */
export const UNIT_ROUNDOFF = 2 ** -53;

// ---- roots (owned by src/roots) -------------------------------------------------------------
// (the roots module appends its named tolerances here)

/**
 * Degree drop in realRoots: the leading coefficient c_n is dropped when, for some j < n,
 * |c_n|·M^(n−j) < ROOTS_DEGREE_DROP·|c_j| with M = max(|lo|, |hi|) (strict, so a zero c_j never
 * qualifies). Then |c_n tⁿ| < u·|c_j t^j| on the whole interval: the term is below one rounding of a
 * lower coefficient, so it cannot change the
 * monotone structure except where p is at its rounding-noise level. Relative, never absolute: scaling
 * the coefficients or the interval by any factor gives the same decision. Roots are still certified
 * against the full polynomial, so the drop only decides the splitting and the cost.
 */
export const ROOTS_DEGREE_DROP = UNIT_ROUNDOFF;

/**
 * Plain Horner error bound factor: |fl(p(x)) − p(x)| ≤ γ₂ₙ·p̃(|x|) with γ₂ₙ = 2nu/(1 − 2nu)
 * (Higham, Accuracy and Stability, eq. 5.3). 2.5·n·u covers γ₂ₙ and the rounding of the computed p̃.
 * |p(x)| within this bound is also the solver's "rounding noise" test for grazing (double) roots.
 */
export const PLAIN_HORNER_BOUND_FACTOR = 2.5;

/**
 * Compensated Horner error bound factor: |CompHorner(p, x) − p(x)| ≤ u|p(x)| + γ₂ₙ²·p̃(|x|)
 * (Graillat, Langlois, Louvet 2005, Theorem 3). γ₂ₙ² ≈ 4n²u²; the factor 8 covers that, the
 * rounding of the computed p̃ and replacing |p(x)| by the computed value (division by 1 − u).
 */
export const COMP_HORNER_BOUND_FACTOR = 8;

/**
 * Iteration cap of every root-refinement loop. Each loop bisects in the ordering of doubles after a
 * few Newton steps, which reaches adjacent doubles in at most 64 + 53 halvings; the cap (well above)
 * is only a guard: exceeding it throws RootSolverError rather than looping or guessing.
 */
export const ROOTS_MAX_ITERATIONS = 400;

/**
 * Bernstein subdivision in the quartic hot path (roots/quartic.ts): growth of the coefficients'
 * rounding margin per de Casteljau halving, relative to the depth-0 margin 24u·scale. A halving's
 * four rounds of averaging add at most 4u·max|b| ≤ 4u·scale; 0.25 gives 6u·scale (1.5× that).
 */
export const ROOTS_SUBDIVISION_MARGIN_GROWTH = 0.25;

/**
 * The quartic hot path's Halley iteration stops once Newton's step is below this fraction of |x|
 * (newton.ts uses 2^-17, for about one ulp): with cubic convergence the error left is about its
 * cube, 2^-33 relative at a simple root, and the certified refinement's first step (Newton's, from
 * a compensated value) takes that to rounding level within its model's span (2^-30 relative);
 * when it cannot, the general refinement finishes. Only the speed depends on it, not the result.
 */
export const ROOTS_HOT_HALLEY_STOP = 2 ** -11;

/**
 * The quartic hot path's certified local model (roots/quarticRefine.ts): |h| ≤ this·|x0|. Over the
 * span p̃″ grows by at most (1 + 2^-12)² − 1 < 2^-10 (degree 4), inside MODEL_SAFETY's 1% (certify.ts
 * uses 2^-30 for any degree); and y − x0 stays exact (Sterbenz). Wider than 2^-30 so that a
 * Halley start only ~2^-25 accurate still gets its ulp from one compensated evaluation.
 */
export const ROOTS_HOT_MODEL_SPAN = 2 ** -12;

/**
 * Cauchy's bound on the roots, 1 + max|c_i| / |c_n| (realRoots.ts, quartic.ts), is computed in
 * doubles: a division and an addition, two roundings of at most 2^-53 each. Widening it by 2^-48
 * relative (far more than those) makes the computed bound an upper bound of the exact one, so that
 * clamping an infinite or huge interval to it never cuts off a root.
 */
export const ROOTS_CAUCHY_WIDENING = 2 ** -48;

/**
 * The general certified refinement's local model (roots/certify.ts): around x0, p is modelled by its
 * Taylor terms with a certified bound on the rest over |h| <= ROOTS_MODEL_SPAN·|x0|, where p̃″ stays
 * within 1 + n·2^-30 of its value at x0; below |x0| = ROOTS_MODEL_MIN_X the h² terms could reach the
 * subnormal range, so no model is used; ROOTS_MODEL_SAFETY (1 %) covers the rounding of the error
 * terms and that growth of p̃″ over the span (and the hot path's, ROOTS_HOT_MODEL_SPAN). They only
 * decide when the model is used: a root it cannot certify is refined by exact signs instead.
 */
export const ROOTS_MODEL_SPAN = 2 ** -30;
export const ROOTS_MODEL_MIN_X = 2 ** -400;
export const ROOTS_MODEL_SAFETY = 1.01;

// ---- simulation (owned by src/sim and src/physics) -----------------------------------------
// (the simulation appends its named tolerances here)

/**
 * Reach, in contact distances, over which a contact polynomial is solved as it stands
 * (physics/farContact.ts). The gap |d(t)|^2 - R^2 of a pair whose relative path spans a length M
 * has terms of size M^2 that cancel to R^2 at the contact, so its rounding error is about
 * UNIT_ROUNDOFF * M^2: with M up to 1024 R that is below 1e-10 R^2 (well inside OVERLAP_REL). Past
 * this reach the far part of the path is cut at the extrema of the distance and each approach is
 * re-anchored at its closest point, where the terms are of size R again (a disc dropped from 1e8
 * radii onto a point was missed without this).
 */
export const FAR_CONTACT_REACH = 1024;

// ---- scene validation (owned by src/scene and src/timeline) ---------------------------------
/** Relative slack when refusing overlaps at an edit (the scene file's check and the World's own, the
 *  same): two discs overlap when their distance is below (r1 + r2)(1 − OVERLAP_REL) (a disc and a
 *  line or point: below r(1 − OVERLAP_REL)). Touching bodies are allowed, with the round-off of
 *  their coordinates (discs packed sqrt(3) apart touch only to the last digit) and the round-off
 *  overlaps (a few ulps) that collisions leave between bodies in contact, so that editing a resting
 *  body is not refused for round-off the engine produced. Such a pair collides at once if it
 *  approaches and never if it separates. */
export const OVERLAP_REL = 1e-9;

/**
 * Largest magnitude the World accepts for a length (position, radius, line or point coordinate)
 * or a rate (velocity, g, gravity, mu); and the smallest radius. The contact polynomials multiply
 * up to four such quantities together (the discriminant c1^2 - 4 c2 c0 of a gap of size s closing
 * at speed s is of order s^4): at s = 1e77 it overflows and at s = 1e-90 it underflows, and the
 * contact is missed without a word. Within [1e-30, 1e30] every such product stays within about
 * 1e+-240, far from both ends of the double range (1e+-308).
 */
export const MAGNITUDE_MAX = 1e30;
/**
 * Largest magnitude of a speed component, a starting position and the position now of a motion a
 * user gives `addBodyMotion`. Such a motion is not held to MAGNITUDE_MAX, since a World's own
 * motions leave it (gravity 1e30 for 2 s gives a speed of 2e30) and what `motion(id)` reports must
 * go back in; but the contact polynomials still multiply up to four such quantities: at about
 * 1e154 the squared speed overflows to Infinity and the pair test finds no root (a disc restored
 * at vx = 1e200 flew through the disc in its path without a word: session 30). At 1e70 the
 * products stay within about 1e+-280 with radii down to RADIUS_MIN. Every speed a World reaches
 * in the documented range lies far inside it (2e60 at most under gravity, TIME_MAX), but not every
 * position: the largest motion ends near 2e90 (TIME_MAX's reason), so its `motion(id)` is refused
 * by `addBodyMotion` there (a known limit, session 31). (MASS_MIN's reason takes the same bound.)
 */
export const MOTION_MAGNITUDE_MAX = 1e70;
/** Smallest radius the World accepts (see MAGNITUDE_MAX: below it the contact polynomials underflow). */
export const RADIUS_MIN = 1e-30;
/**
 * Smallest non-zero speed component an edit may give (0 is allowed): the squared relative speed of
 * a pair at 1e-170 underflows to 0 and the pair is taken for one that never meets.
 */
export const SPEED_MIN = 1e-30;
/**
 * Smallest non-zero friction field g, friction coefficient mu and gravity component an edit may
 * give (0 is allowed). The contact quartic's leading coefficient is |w|^2 / 4 for a relative
 * acceleration w: below about 1e-154 it underflows to 0 and the solver works on a polynomial that
 * is not the gap (a disc under gravity 1e-200 "touched" a point while still 0.67 radii from it:
 * review). With g, mu >= 1e-30, mu g >= 1e-60 and |w|^2 stays above 1e-150 even when two such
 * accelerations nearly cancel.
 */
export const FIELD_MIN = 1e-30;

/**
 * Largest magnitude of a time given to the engine: an action's time in a scene or a Timeline, the
 * World's `time` option, and every time a computation is asked to reach or a World is read at:
 * `advance({ untilTime })`, `body(id, t)` and the other reads of a World, `prolongTo(t)`, the horizon
 * plus a prolong's `until.time`, an action's time plus its `until.time`, the command line's times
 * (sim/timeLimit.ts). A time enters the state as v·t and a·t²/2 (a body given a velocity at
 * t = 1e300 was at x = 1e300 a moment later, beyond MAGNITUDE_MAX: audit of session 19). Within
 * |t| ≤ TIME_MAX every motion an edit allows stays finite: the largest, from (-1e30, 1e30) at speed
 * 1e30 under gravity and friction fields of 1e30 over the whole span -1e30 to 1e30, ends near 2e90
 * with a speed of 2e60 (sim/timeLimit.test.ts); a friction motion stops by then. Past it the doubles
 * give out: gravity 1e30 puts a body at y = -Infinity from about t = 1e139, and
 * `advance({ untilTime: 1e200 })` did so without a word, after which the World placed bodies and
 * took edits against a body at -Infinity (session 31); and one rounding of the time, ulp(1e30) = 1.4e14,
 * is already larger than most discs, so no contact can be placed there anyway. Decision: a time
 * limit or read time past TIME_MAX (and past where the clock already is) is refused before
 * anything is computed, naming the field, the value and the time it would reach; leaving the
 * limit out (`untilTime: Infinity`, the documented default, stays allowed) and bounding a run by
 * events (`maxEvents`, `until.events`) lets the clock pass TIME_MAX, at the events' own times,
 * where the states are those the events computed. Rejected: letting the clock pass and refusing
 * only the reads whose value is not finite, since the World's own edits and predictions then
 * still work from the non-finite state; and stopping at TIME_MAX, a silent cap. Checked once per
 * call, never per event. What a computation reached past it (a keyframe, a motion's t0) is
 * restored as it is. Far below this bound a time is already coarse: ulp(1e9) is 1.2e-7 (README:
 * precision of absolute times).
 */
export const TIME_MAX = MAGNITUDE_MAX;

/**
 * Smallest and largest finite mass an edit may give (Infinity stays allowed: immovable). Masses
 * enter the response as the shares 2 m2 / (m1 + m2), in (2e-80, 2) for masses within 1e±40, and the
 * impulse 2 m1 m2 / (m1 + m2) · approach: m1·m2 stays within 1e±80, a normal double, so the plain
 * formula holds (no rescaling), and an impulse or a momentum m·v at the speeds the contact
 * polynomials allow (below about 1e70, see MAGNITUDE_MAX) stays within 1e110. A light body struck
 * by a heavy one gains at most sqrt(M / m) ≤ 1e40 times the heavy one's speed (energy), so input
 * speeds up to MAGNITUDE_MAX stay below 1e70 there. Outside, two discs of mass 1e308 reported an
 * impulse of Infinity (2 m v overflows; Infinity means two immovable bodies) and 5e-324 left the
 * impulses subnormal (audit of session 19). Within it: an electron (9.1e-31 kg) to a star (2e30 kg),
 * Galperin's billiard to 9 digits (mass ratio 1e16) and beyond.
 */
export const MASS_MIN = 1e-40;
/** Largest finite mass an edit may give (see MASS_MIN). */
export const MASS_MAX = 1e40;

/**
 * Cell side of the broad-phase grid relative to the largest diameter. Slightly above 1 so that a
 * body whose centre sits a rounding error outside its recorded cell still finds every partner it
 * can touch in the 3x3 neighbourhood.
 */
export const GRID_CELL_MARGIN = 1 + 1e-6;

/**
 * A segment or ray is registered in every grid cell it passes through (sim/rasterize.ts), each cell
 * widened by GRID_SEGMENT_PAD of the cell width: a segment along a cell border, or through a corner,
 * computed to pass a rounding outside a cell, is registered on both sides, so a disc in either cell
 * finds it. Relative to the cell width, so the same at any scale; far above the rounding of the
 * clipping (a few ulps of the coordinates), far below anything that costs a scan.
 */
export const GRID_SEGMENT_PAD = 1e-9;

/**
 * The placement checks find the obstacles near a disc, and the bodies near an obstacle, in spatial
 * indexes (sim/obstacleCells.ts, sim/bodiesNear.ts, scene/discGrid.ts) instead of testing every
 * pair; each box they look in or register in is widened by PLACEMENT_INDEX_PAD times the sum of the
 * magnitudes of its coordinates. An overlap test computed in doubles errs by a few ulps of the
 * coordinates it reads (about 1e-15 of them), so a pair it calls overlapping has boxes that share a
 * cell: the refusals are exactly those of a scan. Far above that rounding, far below any size that
 * costs a scan (a disc at 1e6 looks 1e-6 further).
 */
export const PLACEMENT_INDEX_PAD = 1e-12;

/**
 * Below this many bodies the layout sized by the bodies is a single cell: testing every pair costs
 * less than the cell-crossing events a grid would add (Galperin's billiard: 2 bodies, millions of
 * events). Many segments or points still get cells (the obstacle layout, GRID_OBSTACLE_GAIN).
 */
export const GRID_MIN_BODIES = 32;

/**
 * Target number of grid cells per body. Cells never get smaller than GRID_CELL_MARGIN * the largest
 * diameter; in dilute scenes they are made larger so that there are at most this many cells per
 * body: fewer cell crossings per collision at the price of a few more pair tests (measured on the
 * 10% gas: 2–4 is the optimum). Larger cells are slower, never wrong.
 */
export const GRID_CELLS_PER_BODY = 3;

/**
 * Calendar event queue (sim/calendarQueue.ts; its width in sim/calendarWidth.ts): the bucket width aims at this many queue entries
 * falling due per bucket (a small front heap, few empty buckets), and the queue rebuilds with a new
 * width when the measured count drifts by more than CALENDAR_REBUILD_FACTOR either way. Only speed
 * depends on them: the pop order is (time, canonical order) whatever the width.
 */
export const CALENDAR_BUCKET_TARGET = 2;
/**
 * The calendar queue rebuilds with a new bucket width when the measured entries per bucket exceed
 * CALENDAR_BUCKET_TARGET times this factor or fall below the target divided by it.
 */
export const CALENDAR_REBUILD_FACTOR = 4;

/**
 * Events processed at one and the same instant before the world reports a Zeno state (infinitely
 * many events in no time) instead of looping. A Newton's cradle of n discs needs n; the limit is
 * per body so that large simultaneous chains are still allowed.
 */
export const SIMULTANEOUS_EVENTS_PER_BODY = 64;

/**
 * ... or SIMULTANEOUS_EVENTS_PER_PAIR per pair of bodies (n (n - 1) / 2 pairs), when that is more:
 * an impulse passing through a cluster of exactly touching discs is resolved pair by pair at one
 * instant, and in a lattice with loops (a rack) the pairs' impulses die away geometrically, in a
 * number of events that grows faster than n. Measured on the break of square racks of touching
 * discs: 6,062 events at one instant for 401 bodies, 40,079 for 901, 140,613 for 1,601 (0.04 to
 * 0.055 per pair of n², growing slowly). 64 per body refused the 40 x 40 rack, with or without
 * friction, at the cue ball's first contact (review). The price: a true Zeno state at one instant
 * (a ball at rest on a floor under gravity) in a scene of 10,000 bodies is reported after ~2.5e7
 * events instead of 6.4e5.
 */
export const SIMULTANEOUS_EVENTS_PER_PAIR = 0.5;

/**
 * ... or this many per body times the square root of the ratio of the heaviest to the lightest
 * finite mass, when that is more: a burst at one instant among touching bodies of very different
 * masses is finite but long, its count growing like sqrt(M / m). Measured with the bodies touching:
 * Galperin's billiard (a light disc between a wall and a heavy one) makes pi sqrt(M / m) collisions
 * (3,141 for M / m = 1e6: 1.6 per body per sqrt), a light disc between two heavy ones 0.74 per
 * body per sqrt, two light ones between two heavy 1.25. Without this term the README's billiard
 * started touching was refused as a Zeno state from M / m = 1,700 (review). The allowance lasts
 * only while collisions of two different finite masses keep coming (the plain limit counts the
 * events since the last of them: zenoWatch.ts). The price: a true Zeno state at one instant that
 * keeps colliding masses of ratio R is reported after up to 4 sqrt(R) n events. Infinite masses are
 * left out of the ratio (a disc jammed between two immovable bodies is reported as soon as without
 * them).
 */
export const SIMULTANEOUS_EVENTS_PER_MASS_SPREAD = 4;

/**
 * Zeno watch over runs of events, active while an immovable (infinite-mass) body moves (without one,
 * elastic and frictional collisions cannot feed energy in, so events cannot converge on a finite
 * time): events are counted in windows of ZENO_WINDOW_EVENTS (at least; ZENO_WINDOW_EVENTS_PER_BODY
 * per body in large scenes), and the windows' durations are compared with each other (ZENO_SHRINK,
 * ZENO_STREAK_PROGRESS below). ZENO_MIN_PROGRESS was the earlier rule's bound on a window's progress
 * relative to |t|; nothing uses it now, and it stays exported because it is public.
 */
export const ZENO_WINDOW_EVENTS = 200_000;
/**
 * Events per body in a Zeno watch window in large scenes: a window holds
 * max(ZENO_WINDOW_EVENTS, ZENO_WINDOW_EVENTS_PER_BODY × bodies) events (see ZENO_WINDOW_EVENTS).
 */
export const ZENO_WINDOW_EVENTS_PER_BODY = 20;
/**
 * The earlier Zeno rule's bound on a window's progress relative to |t| (see ZENO_WINDOW_EVENTS).
 * @deprecated Unused; kept because it is exported.
 */
export const ZENO_MIN_PROGRESS = 1e-6;

/**
 * The Zeno watch's test of convergence (sim/zenoWatch.ts), replacing the comparison of a window's
 * progress with ZENO_MIN_PROGRESS × |t| (which now serves nothing): that comparison depends on the
 * time origin, so it refused a legitimate disc rattling between walls 1e-4 apart at 1e3 speed at
 * t = 1e5 (a steady 1e7 events per second beside a moving immovable disc), and never reported a
 * crush that converges on t = 0 (it ran 3e7 events and on). A run converges when each window of
 * events lasts at most ZENO_SHRINK times the one before and one lasts at most ZENO_STREAK_PROGRESS
 * times the whole run before it. A steady rattle's windows are equal up to noise, so its run of
 * shrinking windows stops within a few windows; one that keeps shrinking by 1 % per window needs
 * about 70 windows in a row to pass the second test (0.99^-70 ≈ 2). A crush, whose event intervals
 * shrink as 1/k², passes both within about ten windows of its start.
 */
export const ZENO_SHRINK = 0.99;

/**
 * The push watch (sim/pushWatch.ts): a body that stops ZENO_PUSH_STREAK times in a row at the very
 * position, to the bit, where it was set in motion (with no stop that moved it, and no edit of it,
 * in between) is pushed along against friction by another, a sustained push, and reported instead
 * of computed: in the break of a 30 x 30 rack (mu 0.1, g 9.81) three events per 8e-14 s, ~1e12
 * events for the push's 0.075 s (review). Streaks of up to ZENO_PUSH_BODIES bodies are kept at once,
 * the shortest giving way. A window test (a share of micro-stops among the events) was refused by
 * a game of 5,355 ordinary breaks, each with 6 micro-stops among 47 events (review).
 */
export const ZENO_PUSH_STREAK = 100_000;
/** Bodies whose streaks of stops the push watch follows at once (the shortest streak gives way; see ZENO_PUSH_STREAK). */
export const ZENO_PUSH_BODIES = 4;
/**
 * The Zeno watch's second test (see ZENO_SHRINK): a run of shrinking windows is reported (while an
 * immovable body moves) once a window lasts at most this fraction of the whole run before it.
 */
export const ZENO_STREAK_PROGRESS = 0.01;

/**
 * The trap watch (sim/trapWatch.ts, its proofs in sim/pocket.ts, sim/lineCrush.ts and
 * sim/lineWatch.ts): a disc shut in a pocket of two or three still sides (lines, points, immovable
 * discs at rest) and the moving immovable disc that closes the pocket before anything can change
 * that disc's motion is crushed: infinitely many events before the pocket closes (so is a disc, or
 * a row of discs, pressed in line against a still end, all symmetric about an axis-parallel line,
 * with no other disc able to reach them in time). The proof is geometric, so that such a crush is reported after
 * hundreds or thousands of events instead of the 2.2 to 2.4 million the windows' convergence test
 * (ZENO_SHRINK) needs: a disc crushed into a corner by an immovable disc falling in under gravity
 * took 2.4 million events and 6 to 19 s (review, session 22); 256 to 2,560 events now
 * (sim/trapWatch.test.ts). The proof keeps its sets ZENO_TRAP_SLACK × r inside the disc's true
 * ones (r its radius), and tests with further margins of that size, so that neither the round-off
 * overlaps between the disc and what touches it nor the proof's own round-off can decide it; and
 * it is tried only where that round-off is far smaller: every magnitude in it (coordinates, radii,
 * the time × the speeds) at most ZENO_TRAP_SCALE × r, whose 16 ulps are 2^-24 r, 1/256 of the
 * slack. Beyond that the windows still report the crush.
 */
export const ZENO_TRAP_SLACK = 2 ** -16;
/** Largest magnitude, in radii of the trapped disc, that the trap watch's proof accepts (see ZENO_TRAP_SLACK). */
export const ZENO_TRAP_SCALE = 2 ** 24;
/**
 * The trap watch reports a proven crush once the moving immovable disc is within this fraction of
 * the trapped disc's radius of closing the pocket, not as soon as it is proven (which can be while
 * the disc still moves freely in a wide pocket): the history then shows the disc rattling ever
 * faster, and the report comes shortly before the crush (a thousandth of its time or less in the
 * tests). About 65 times ZENO_TRAP_SLACK, so that the proof's margins (a few slacks) barely delay it.
 * The price: an action scheduled between the report and the crush is not reached (it was the same
 * with the windows, over a shorter stretch).
 */
export const ZENO_TRAP_GAP = 1e-3;
/**
 * The trap watch tries its proof at a collision between a finite disc and a moving immovable one
 * only while the Zeno watch's count of events in its window, modulo ZENO_TRAP_EVERY (a power of
 * two), is below ZENO_TRAP_TRIES: the proof scans every obstacle and immovable disc, and a pump
 * stirring a large gas must not pay that at each of its collisions. 16 consecutive counts of every
 * 256 hold collisions of the crushed disc with the crusher whatever the period of the pattern of
 * its collisions (up to 16): a crush is tried every 256 events or so.
 */
export const ZENO_TRAP_EVERY = 256;
/** Consecutive event counts, of every ZENO_TRAP_EVERY, at which the trap watch tries its proof. */
export const ZENO_TRAP_TRIES = 16;
/**
 * The obstacles and immovable discs nearest the disc (by the gap to its surface) that the trap
 * watch tries, in chains of two and three, as the pocket's still sides: 15 pairs and 60 chains of
 * three of 6. A pocket closing on the disc has its sides within a small gap of it, so the nearest
 * are its sides, unless more than 6 crowd there (a corner of many short segments), when the
 * windows still report the crush.
 */
export const ZENO_TRAP_CANDIDATES = 6;

/**
 * Before the grid had levels: the most "big bodies" (discs over GRID_BIG_RATIO times the next
 * largest) kept out of the grid's cells.
 * @deprecated Unused since the grid has levels (sim/grid.ts); kept because they are exported.
 * They bounded the "big bodies" kept out of the cells and tested against every body: at most
 * GRID_BIG_BODIES_MAX discs more than GRID_BIG_RATIO times the next largest. A 9th disc of radius 20
 * among 10,000 of radius 1 made every cell fit radius 20 (100 of them: 2 times slower than now).
 */
export const GRID_BIG_BODIES_MAX = 8;
/**
 * Ratio of radii that made a disc "big" before the grid had levels.
 * @deprecated Unused; see GRID_BIG_BODIES_MAX.
 */
export const GRID_BIG_RATIO = 2;

/**
 * Levels of the broad-phase grid (sim/grid.ts, sim/gridCost.ts): a grid of several levels is built
 * only when its estimated cost per prediction is at most GRID_LEVEL_GAIN of one level sized for
 * the largest disc. The estimate counts pair tests and cell visits only; levels also add cell
 * crossings (smaller cells) and a loop over the levels, which the margin pays for. Measured on
 * 10 % gases of 10,000 discs (estimate levels / one level, then speed with levels against one
 * level): one disc of radius 2.5 among radius 1, 0.60 and 1.2 times faster; radii spread evenly on
 * a log scale from 1 to 30, 0.87 and 30 % slower (so one level); 1,000 discs of radius 3, 1.02 (one
 * level); 100 of radius 20, 0.10 and 2 times faster. GRID_CELL_VISIT_COST is the cost of visiting
 * an empty cell, in pair tests (a load and a branch against a pair test's dozens of operations).
 * Only speed depends on them, never a result.
 */
export const GRID_LEVEL_GAIN = 0.65;
/** Cost of visiting an empty grid cell, in pair tests, in the grid's cost estimate (see GRID_LEVEL_GAIN). */
export const GRID_CELL_VISIT_COST = 0.1;

/**
 * The grid for scenes of many obstacles (segments and points) and few bodies (sim/broadPhase.ts,
 * sim/gridCost.ts `eventCost`): the cost of one collision is estimated, in pair tests, for the
 * layout sized by the bodies alone (a single cell below GRID_MIN_BODIES) and for cells sized to
 * minimise it over the box holding bodies and obstacles; the second is taken only when it costs at
 * most GRID_OBSTACLE_GAIN of the first, so scenes the body layout suits (Galperin's billiard: 2
 * discs and a line, the gases in a box of 4 walls) keep it. The constants below calibrate the
 * estimate; only speed depends on them, never a result. Calibrated by hand on a noisy 2-core host
 * (24 Nov 2026, CPU µs per event, one cell against the layout the estimate picks): 8 discs in a
 * maze of 9 segments 3.9 and 2.9 (estimate 0.79 of one cell: one cell kept), of 16 segments 4.6
 * and 3.0 (0.72: one cell kept), of 30 segments 6.6 and 3.3 (0.48); 2 discs among 16 segments 3.2
 * and 3.5 (0.91: one cell kept, rightly); 1 ball among 40 pegs 8.4 and 5.0 (0.56). The measured
 * ratio ran from 0.1 below to 0.3 above the estimate, hence the margin. A maze of 10,000 segments
 * went from ~1,200 to ~3-9 µs per event; the gases in a box of 4 walls (estimate ~1.0) keep the
 * body layout.
 */
export const GRID_OBSTACLE_GAIN = 0.7;
/** Fixed cost of a prediction in pair tests (the heap update, the stop, the loop set-up): see GRID_OBSTACLE_GAIN. */
export const GRID_PREDICTION_COST = 8;
/** Fixed cost of a cell crossing in pair tests (its event, the move, the exit time): see GRID_OBSTACLE_GAIN. */
export const GRID_CROSSING_COST = 6;
/** Predictions per collision (2 for a disc pair, 1 against an obstacle): see GRID_OBSTACLE_GAIN. */
export const GRID_PREDICTIONS_PER_EVENT = 1.5;
/**
 * A segment's test (its interior and two end points) in pair tests (measured: 8 discs among 1,000
 * segments or 5 balls among 1,000 points, one cell, ~120 and ~100 ns per obstacle per event): see
 * GRID_OBSTACLE_GAIN.
 */
export const GRID_SEGMENT_TEST_COST = 1.5;
/**
 * Most level-0 cells of the obstacle layout per body and obstacle (and at least 16): memory and
 * rebuild time stay O(bodies + obstacles). See GRID_OBSTACLE_GAIN.
 */
export const GRID_CELLS_PER_ITEM = 16;

/**
 * An edit of a segment or point keeps the grid's layout (sim/obstacleUpkeep.ts: the obstacle is
 * registered in, or taken out of, the cells it covers, and only the bodies it can concern are
 * predicted again) while the segments and points number at most GRID_OBSTACLE_RELAYOUT times what
 * the layout was computed for (counted as at least GRID_MIN_BODIES) and, when that was more than
 * GRID_MIN_BODIES, at least 1 / GRID_OBSTACLE_RELAYOUT of it. Past that, the cost estimate that
 * chose the layout (GRID_OBSTACLE_GAIN), which grows with them, is evaluated again: when it picks
 * the other kind of layout (sized by the bodies, or by the obstacles) or cells more than
 * GRID_OBSTACLE_RELAYOUT times larger or smaller, the grid is laid out again and every body
 * predicted; otherwise the range starts again from there. A stream of m edits so evaluates the
 * estimate O(log m) times. Only speed depends on it.
 */
export const GRID_OBSTACLE_RELAYOUT = 2;

/**
 * A touching pair (disc–disc, disc–point, disc–line) counts as approaching only when its gap
 * shrinks faster than APPROACH_NOISE times the sum of the magnitudes of the products that make up
 * the rate (physics/timeOfImpact.ts, physics/farContact.ts): 16 roundings, well above the few
 * a dot product and the response make. Below that the sign of the rate is rounding noise; the
 * response (its own rounding) then found no approach, or a change below one ulp of the velocities,
 * and the same contact was found again at once, for ever: a disc sliding along a tilted line was
 * reported as a Zeno state in 27 of 200 slopes, and a cue ball breaking a 20 × 20 rack of touching
 * discs cycled on one pair with an impulse of 3.5e-19, and under friction a 12 × 12 one with an
 * impulse of 0 (review). A graze below it lets a pair close
 * by at most that rate: 16 u of the speed, 2e-15 of the distance travelled.
 */
export const APPROACH_NOISE = 16 * UNIT_ROUNDOFF;

/**
 * A touching pair's approach counts only when the response can act on it: when d.u exceeds
 * 2 RESPONSE_ULP of |dx| (|vx1| + |vx2|) + |dy| (|vy1| + |vy2|), the same product from the two
 * bodies' own velocity components (an ulp of a number is at most 2 rounding units of it), so that
 * the lighter body's velocity changes by about an ulp and the pair parts. Below that the response
 * changed nothing and the same contact was found again at once, for ever: two discs sliding side by
 * side at 0.6 in a rack break under friction approached at 1.7e-16 (review). An approach slower
 * than this passes: two discs whose velocities along the line of centres are about V may close by
 * up to ~8 u V per unit of time (a frictionless pair closing at 3e-13 while both move at 1000
 * across that line collides; with the bodies' whole speeds as the scale it passed: review).
 */
export const RESPONSE_ULP = 2 * UNIT_ROUNDOFF;

/**
 * A pair's relative acceleration w is dropped when w tau^2 / 2 stays below NEGLIGIBLE_DRIFT times
 * the contact distance until either motion ends (physics/timeOfImpact.ts discDiscTime): 16
 * roundings of the contact distance, below what the positions themselves carry. Two discs in
 * the last nanoseconds before friction stops them, touching and pressed together by their
 * decelerations, had a contact a fraction of an ulp of time ahead; at the rounded time the
 * response saw no approach, and the break of a 20 x 20 rack under friction was refused as a Zeno
 * state (review). On the straight path the touching pair is a graze.
 */
export const NEGLIGIBLE_DRIFT = 16 * UNIT_ROUNDOFF;

/**
 * A disc touching a line (its gap within the rounding of its position, or inside it by the slack
 * OVERLAP_REL allows) that moves away but is turned back by an acceleration before its gap exceeds
 * CONTACT_BAND times the magnitudes that make up the gap (the coordinates of the centre and of the
 * line's point, each weighted by the normal's component along it, and r) never leaves the contact: a resting contact, refused as such
 * (physics/timeOfImpact.ts). 16 roundings of those magnitudes, above what the position carries.
 * Without it a disc placed on a ramp under gravity took one of three courses by how its slope
 * rounded: refused as resting (as on a flat floor), bouncing ever lower at the rounding level
 * (2,000,000 events in 8e-8 s at 10°), or, left a rounding inside the line and rising too little
 * to get out, never meeting it again and falling through (20°, 30°: audit of session 17).
 */
export const CONTACT_BAND = 16 * UNIT_ROUNDOFF;

/**
 * On a straight path (uniform or under friction), a contact with an end of a ray or segment counts
 * only if the centre at the contact is not inside the solid part (along the line, from that end) by
 * more than END_INSIDE_SLACK times the magnitudes of the contact (the centre's and the end's
 * coordinates, and r). A centre inside is at most r from the line, so the interior touched first
 * or at the same time and lineTime owns that contact; an end-point contact found there is the
 * rounding of a graze: a disc sliding along the wall (touching, not approaching it) past its end,
 * whose gap to the end dipped a rounding below 0. Its entry lies about sqrt(2 r delta) before the
 * end for a gap rounded by delta, far above this slack (1,024 roundings) unless the coordinates are
 * some 10^10 radii; the centre's own rounding near a genuine hit on the end is a few roundings, far
 * below it. Without it a disc sliding under friction along a tilted channel of segments exactly
 * its diameter wide took a tiny impulse at the wall's end and bounced between the two walls it
 * touched: a Zeno error (session 25; the axis-parallel channel is exact: contactTimes.ts onEdgePath).
 */
export const END_INSIDE_SLACK = 1024 * UNIT_ROUNDOFF;

/**
 * On a straight path, an end of a ray or segment that lies r from the path's line within
 * GRAZE_SLACK times the magnitudes of the contact (as END_INSIDE_SLACK) is passed untouched: a
 * graze, whose exact gap touches 0 and never crosses it (a disc entering, leaving or sliding along a
 * channel of tilted segments exactly its diameter wide; the axis-parallel case is exact:
 * contactTimes.ts onEdgePath). The rounding of the path's direction and of the end's coordinates
 * moves that distance by a few roundings of the magnitudes; 64 of them leave a disc passing that
 * close overlapping the end by at most 64 roundings of its coordinates.
 */
export const GRAZE_SLACK = 64 * UNIT_ROUNDOFF;

/**
 * At a collision the centres are the contact distance D apart (r1 + r2, or r from a line or point)
 * up to a few roundings of the coordinates. When, as doubles, they are farther than
 * CONTACT_UNRESOLVED_FRACTION·D from it, the coordinates are so large against the radii that their
 * rounding is of the size of the discs (|x| ≳ 2^52 r: a disc of radius 1 at x = 1e16): the contact
 * normal is then meaningless (0/0 when two centres round to one double, which gave NaN normals and
 * discs passing through each other; a centre rounded onto a wall's line was taken for a Zeno state:
 * audit of session 20). Such an event throws a SimulationError that says so (physics/resolution.ts).
 * At any scale the doubles resolve, the offset is a few ulps of D, so 1/2 never fires there.
 */
export const CONTACT_UNRESOLVED_FRACTION = 0.5;

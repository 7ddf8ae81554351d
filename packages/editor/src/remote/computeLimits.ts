/**
 * The limits the host's computation keeps (hostCompute.ts), each with its reason: how long a round
 * of slices may take before messages are answered, how often progress is told and samples are
 * recorded, and how large the stored history may grow before the computation stops.
 */

/**
 * Wall-clock milliseconds one round of slices may take before the host yields to messages (a frame
 * or scrub request waits at most about this long while computing).
 */
export const ROUND_MS = 8;
/**
 * While computing, the host tells the client about progress at most this often (ms): each `info`
 * re-renders the panels that show counts and the horizon on the main thread, and rounds end 100
 * times a second. The revision moves only when info is sent, so frames and info always agree.
 */
export const INFO_EVERY_MS = 50;
/**
 * A computation stops once the stored history (Timeline.historyBytes: records and keyframes) passes
 * this many bytes, saying so in `info.stopped`: a scene that never comes to rest computed with ∞
 * grew to 1.6 GB and ended in "Array buffer allocation failed" (review, session 19). About 10
 * million events of a 200-disc gas; a browser tab has a few GB in all. A restore (history the user
 * had, brought back after an edit) is not stopped: it was under the cap when it was computed.
 */
export const HISTORY_MAX_BYTES = 512 * 2 ** 20;
/** How often (ms) a computation compares the history's size with HISTORY_MAX_BYTES. */
export const CAP_CHECK_MS = 100;
/** While computing, energy/event samples are recorded at most this often (ms of wall-clock time). */
export const RECORD_EVERY_MS = 100;

/**
 * USAGE: the text of `chapgame --help`: the commands, their options, the result, how a run ends
 * (bounds, interrupts, errors) and the exit statuses. The README's CLI section says the same at
 * more length; args.ts parses what it describes.
 */

export const USAGE = `Usage:
  chapgame simulate SCENE [--until-time T] [--max-events N] [--events] [--compact] [--progress]
      Run the scene's actions and simulate until time T or N events (collisions and stops),
      whichever comes first; print the bodies then as JSON, with "reason": "time", "events" or
      "idle" (no event and no action left). An idle run's bodies are printed at T with
      --until-time (they may still glide), at the scene's bound with its untils (below), else at
      its last event or action.
      Without --until-time and --max-events, a scene whose actions carry an "until" (seconds
      and/or events to compute after the action) is computed as far as they say: every action
      applied and each until met, counted from its action; "reason" is then "until" (or "idle"),
      and the bodies are printed where it ended. Options given here win: with either of them the
      scene's untils are ignored. With no bound at all the run goes on until no event is left,
      so a scene that never comes to rest (elastic balls bouncing under gravity) runs until
      interrupted. A scene the exact model cannot continue (a Zeno state) prints the result up
      to where it stopped, with "reason": "error" and "error": why, and exits with status 2.
  chapgame state SCENE --at T [--events] [--compact] [--progress]
      Print the bodies at time T as JSON (the actions are computed, and checked, up to T).
      If the exact model cannot continue before T (a Zeno state), it prints the bodies where it
      stopped instead, with "time" there, "reason": "error" and "error": why, and exits with 2.
  chapgame path SCENE --id ID --to T [--from T] [--compact] [--progress]
      Print the exact path of body ID from time --from (default 0) to --to as JSON: "id",
      "from", "to" and "pieces", the motions it followed in time order, each with "from" and
      "until" (the span it covers) and t0, x0, y0, vx, vy, ax, ay, tStop: over its span the body
      is at x0 + d (vx + ax d / 2), d = min(t, tStop) - t0 (y likewise), and rests from tStop on.
      A piece ends at each collision or stop of the body and at each action that restarts it;
      spans where the body does not exist give no piece. --from T --to T (one time) prints the
      one point where the body is at T: a single piece with "from" = "until" = T and the motion
      it follows from T on (as state --at T shows it), or none when it does not exist then.
      An ID no addBody of the scene names is refused (exit 2) with the scene's bodies listed.
      A run the exact model cannot continue before --to prints the pieces up to where it
      stopped, with "to" there, "reason": "error" and "error": why, and exits with 2.
  chapgame check SCENE [--compact] [--progress]
      Check a scene file whole: every field, and every action against the simulation (ids that
      exist, overlaps with bodies that have moved), computing exactly up to its last action, so it
      ends for any scene. Prints {"valid": true, "actions": N, "checkedTo": T, "events": E} and
      exits with 0, or {"valid": false, "error": why, "path": the field or null} and exits with 2
      (the message on stderr too). A Zeno state before the last action makes the scene invalid.
  chapgame --help
  chapgame --version

SCENE is a scene file (format "chapgame", version 1), or - for standard input; after --, a name
that starts with "-" is a file name. A time T is a decimal number from 0 to 1e30 (TIME_MAX, the
bound of every time given to the engine: past it positions under gravity leave the doubles).
A T with more digits than a double holds that reads as another number says so on stderr
("note: --at 0.99999999999999999999999 is read as 1 (the nearest double)") and the run goes on.
Interrupting a run (Ctrl-C: SIGINT, or SIGTERM) while it computes prints the result up to
where it got, with "time" there and "reason": "interrupted" (state too; path: "to" there), and
exits with status 130 (SIGINT) or 143 (SIGTERM); an interrupted check prints nothing on standard
output (it did not finish), only a line on stderr. In a pipeline Ctrl-C reaches the reader as
well: to keep the result, send the signal to chapgame alone (kill -INT PID) or write to a file.
A signal while the result is being written (after the computation) does not cut it short: the
writing goes on to valid JSON, a line on stderr says so, and the status is the signal's; a second
signal (after one that stopped the computation, the first while writing) stops it at once, leaving
the output incomplete, not valid JSON, and says so on stderr.
A scene is read in chunks; one that gives more text than a JavaScript string holds (about 537
million characters) is refused as soon as it does, a device or fifo that never ends (/dev/zero)
too; a long read shows the megabytes read so far (with --progress, or on a terminal).
The result of simulate and state: "time", "reason" (simulate, and a state that stopped early),
"events" (collisions and stops), "counts" (bodyBody, bodyLine, bodyPoint, stop), "bodies" (id, x,
y, vx, vy, r, m, mu at "time", sorted by id) and with --events "log": every entry up to "time"
in order, each with "time", "type" (bodyBody, bodyLine, bodyPoint, stop, action), "ids" (the
participants; the action's id), "point" (contact, or where a body stopped), "normal" (unit, from
the first id to the second), "impulse" (0 for a stop) and, for an action, "action" (its type);
null where it does not apply.
The log also lists the actions, which "events" does not count. Infinite numbers are written
"Infinity" and "-Infinity", NaN "NaN".
--events adds the event log (kept in memory: bound long runs).
--compact writes the JSON without indentation, the log one entry per line (about half the size).
--progress reports progress on stderr about once a second (the first line half a second into the
computation; a run that ends sooner shows none): the time reached (of the time the run computes
to), the events (of --max-events) and, while some are still to come, the actions applied; a scene
of 10 million characters or more also says when it is read and built. It is on by itself, on one
updating line, when stderr is a terminal. The result on stdout is the same with or without it.
Exit status: 0 success, 2 invalid input or a scene that cannot be continued, 1 internal error or
a result that could not be written, 130 or 143 interrupted (SIGINT, SIGTERM).`;

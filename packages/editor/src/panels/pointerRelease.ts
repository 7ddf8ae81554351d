/**
 * afterPointerRelease(fn): runs `fn` now, or, while a pointer button is pressed, once it is
 * released and the click it makes has been dispatched. A field applied on leaving it (pressing a
 * button elsewhere blurs it) takes its refusal down; done at once, the panel's layout moved under
 * the pointer between the press and the release, and the button pressed (Compute under Seconds
 * ahead's refusal, Load preset beside the digits' one) got no click (e2e, session 26). The pressed
 * state is followed by listeners on the window, installed when the module loads: installed at the
 * first call, they missed the press whose blur made that call (the first refusal taken down on
 * leaving a field, as the digits' by pressing Load preset, still moved the button away).
 */

let pressed = false;
let waiting: (() => void)[] = [];
let installed = false;

function install(): void {
  if (installed || typeof window === "undefined") return;
  installed = true;
  window.addEventListener(
    "pointerdown",
    () => {
      pressed = true;
    },
    true,
  );
  const release = () => {
    pressed = false;
    const run = waiting;
    waiting = [];
    // after the click the release makes (dispatched in the same task as the release)
    if (run.length > 0)
      setTimeout(() => {
        for (const fn of run) fn();
      }, 0);
  };
  window.addEventListener("pointerup", release, true);
  window.addEventListener("pointercancel", release, true);
}

install();

export function afterPointerRelease(fn: () => void): void {
  install();
  if (pressed) waiting.push(fn);
  else fn();
}

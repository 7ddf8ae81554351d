/**
 * A button that keeps the keyboard focus when it cannot act: aria-disabled (announced and drawn as
 * unavailable; pressing it does nothing) rather than disabled. A disabled button drops the focus to
 * the page, so a keyboard user who pressed Zoom in to its end, the toolbar's Delete, the last Undo,
 * Next entry at the log's end or Compute (busy while it computes) lost their place in the tab order
 * (audit).
 */
import type { ComponentProps } from "react";

type Props = Omit<ComponentProps<"button">, "disabled" | "onClick" | "type"> & {
  enabled: boolean;
  onPress: () => void;
};

export function FocusKeptButton({ enabled, onPress, children, ...rest }: Props) {
  return (
    <button
      {...rest}
      type="button"
      aria-disabled={enabled ? undefined : true}
      onClick={enabled ? onPress : undefined}
    >
      {children}
    </button>
  );
}

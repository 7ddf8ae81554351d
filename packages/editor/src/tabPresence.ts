/**
 * Which editor tabs of this origin are open, over a BroadcastChannel: a tab says `hello` with its id
 * when it starts, every open tab answers `here` with its own, and a tab going away says `bye`.
 * Two tabs with one id (the browser's Duplicate tab copies sessionStorage, and with it the id): the
 * tab that holds the id answers a `hello` for it with `taken`, and the newcomer takes another id.
 */

/** The part of BroadcastChannel used here. */
export interface TabChannel {
  postMessage(message: unknown): void;
  onmessage: ((e: { data: unknown }) => void) | null;
  close(): void;
}

type Message = { type: "hello" | "here" | "bye" | "taken"; tab: string };

export class TabPresence {
  /** Ids of the other open tabs heard from (a `hello` or a `here`, and no `bye` since). */
  readonly live = new Set<string>();

  /**
   * `tab()`: this tab's id now; `onTaken`: another open tab holds it (take a new id). Says hello.
   */
  constructor(
    private readonly channel: TabChannel,
    private readonly tab: () => string,
    private readonly onTaken: () => void,
  ) {
    channel.onmessage = (e) => this.receive(e.data as Partial<Message> | null);
    this.hello();
  }

  /** Announces this tab's (new) id; an open tab holding it answers `taken`. */
  hello(): void {
    this.channel.postMessage({ type: "hello", tab: this.tab() });
  }

  private receive(m: Partial<Message> | null): void {
    if (typeof m?.tab !== "string") return;
    const mine = m.tab === this.tab();
    if (m.type === "hello") {
      if (mine) this.channel.postMessage({ type: "taken", tab: m.tab });
      else {
        this.live.add(m.tab);
        this.channel.postMessage({ type: "here", tab: this.tab() });
      }
    } else if (m.type === "here") {
      if (!mine) this.live.add(m.tab);
    } else if (m.type === "bye") this.live.delete(m.tab);
    else if (m.type === "taken" && mine) this.onTaken();
  }

  /** This tab goes away (pagehide): the others forget it until it says hello again. */
  bye(): void {
    this.channel.postMessage({ type: "bye", tab: this.tab() });
  }

  close(): void {
    this.channel.onmessage = null;
    this.channel.close();
  }
}

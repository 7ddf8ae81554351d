/**
 * The code of a TypeScript source without its comments and literal text, for audits of what the
 * code calls (exactArithmetic.test.ts). Comments, the text of string and template literals and the
 * bodies of regular-expression literals become spaces; newlines are kept, so offsets and line
 * numbers are the source's. Code inside a template's ${...} stays code. A lexer for audits, not a
 * parser: it knows the tokens that can hide code-like text, nothing more.
 */

/** Characters after which a "/" starts a regular expression rather than a division. */
const BEFORE_REGEX = new Set([
  "",
  "(",
  ",",
  "=",
  ":",
  "[",
  "!",
  "&",
  "|",
  "?",
  "{",
  "}",
  ";",
  "+",
  "-",
  "*",
  "%",
  "<",
  ">",
  "~",
  "^",
]);

const blank = (s: string): string => s.replace(/[^\n]/g, " ");

export function stripCommentsAndStrings(src: string): string {
  let out = "";
  let i = 0;
  // Brace depth of each open template's ${...}: at depth 0, a "}" resumes the template's text.
  const templates: number[] = [];
  const n = src.length;
  /** The last non-space character of the code emitted so far. */
  const lastCode = (): string => {
    const m = /(\S)\s*$/.exec(out);
    if (m === null) return "";
    // A keyword before "/" ("return /x/") also starts a regular expression.
    return /\b(return|typeof|case|in|of)\s*$/.test(out) ? "(" : (m[1] as string);
  };
  /** Skip template text from i (just after "`" or "}"); returns where it stopped. */
  const templateText = (from: number): number => {
    let j = from;
    while (j < n && src[j] !== "`" && !(src[j] === "$" && src[j + 1] === "{")) j += src[j] === "\\" ? 2 : 1;
    out += blank(src.slice(from, j));
    if (j >= n) return n;
    if (src[j] === "`") {
      out += "`";
      return j + 1;
    }
    out += "${";
    templates.push(0);
    return j + 2;
  };
  while (i < n) {
    const c = src[i] as string;
    const next = src[i + 1];
    if (c === "/" && next === "/") {
      const end = src.indexOf("\n", i);
      const j = end < 0 ? n : end;
      out += blank(src.slice(i, j));
      i = j;
    } else if (c === "/" && next === "*") {
      const end = src.indexOf("*/", i + 2);
      const j = end < 0 ? n : end + 2;
      out += blank(src.slice(i, j));
      i = j;
    } else if (c === '"' || c === "'") {
      let j = i + 1;
      while (j < n && src[j] !== c && src[j] !== "\n") j += src[j] === "\\" ? 2 : 1;
      out += `${c}${blank(src.slice(i + 1, j))}${c}`;
      i = j + 1;
    } else if (c === "`") {
      out += "`";
      i = templateText(i + 1);
    } else if (c === "/" && BEFORE_REGEX.has(lastCode())) {
      let j = i + 1;
      let inClass = false;
      while (j < n && src[j] !== "\n" && (inClass || src[j] !== "/")) {
        if (src[j] === "[") inClass = true;
        else if (src[j] === "]") inClass = false;
        j += src[j] === "\\" ? 2 : 1;
      }
      out += `/${blank(src.slice(i + 1, j))}/`;
      i = j + 1;
    } else if (templates.length > 0 && (c === "{" || c === "}")) {
      const depth = templates[templates.length - 1] as number;
      if (c === "{") templates[templates.length - 1] = depth + 1;
      else if (depth > 0) templates[templates.length - 1] = depth - 1;
      else {
        templates.pop();
        out += "}";
        i = templateText(i + 1);
        continue;
      }
      out += c;
      i++;
    } else {
      out += c;
      i++;
    }
  }
  return out;
}

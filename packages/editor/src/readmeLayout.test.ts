/**
 * The editor README's layout table (`## Layout (`src/`)`) is the map of src/: each folder of src/ has
 * a row of its own (its path cell the folder's name, `canvas/`) that names every file in it but its
 * tests, every file directly in src/ but a test is named in some row, and every file the table names
 * exists (in the row's folder, or from src/). A file is named as code: `draw.ts`, or `canvas/draw.ts`.
 */
import { readdirSync, readFileSync, statSync } from "node:fs";
import { join } from "node:path";
import { describe, expect, it } from "vitest";

const SRC = import.meta.dirname;
const README = readFileSync(join(SRC, "../README.md"), "utf8");

const isTest = (name: string) => /\.test\.tsx?$/.test(name);
const isDir = (path: string) => statSync(path).isDirectory();

/** The layout table's rows, each as its path cell and its whole text. */
function layoutRows(): { path: string; text: string }[] {
  const section = /^## Layout \(`src\/`\)\n([\s\S]*?)(?=^## )/m.exec(README);
  if (!section) throw new Error("README.md: no section `## Layout (`src/`)` followed by another section");
  return section[1]!
    .split("\n")
    .filter((line) => line.startsWith("| ") && !/^\| (path|-+) /.test(line))
    .map((text) => ({ path: text.split("|")[1]!.trim(), text }));
}

/** The file names a text names as code (names with an extension, inside backticks). */
const filesNamed = (text: string) => [...text.matchAll(/`([\w./-]+\.(?:tsx?|css))`/g)].map((m) => m[1]!);

describe("the editor README's layout table", () => {
  const rows = layoutRows();
  const folders = readdirSync(SRC).filter((name) => isDir(join(SRC, name)));

  it("has a row for each folder of src/ that names every file in it but its tests", () => {
    expect(folders).toContain("remote");
    const unnamed: string[] = [];
    for (const folder of folders) {
      const row = rows.filter((r) => r.path === `\`${folder}/\``);
      if (row.length !== 1) {
        unnamed.push(`${folder}/ (${row.length} rows)`);
        continue;
      }
      const named = new Set(filesNamed(row[0]!.text).map((f) => f.replace(`${folder}/`, "")));
      for (const file of readdirSync(join(SRC, folder)))
        if (!isTest(file) && !named.has(file)) unnamed.push(`${folder}/${file}`);
    }
    expect(unnamed).toEqual([]);
  });

  it("names every file directly in src/ but its tests", () => {
    const named = new Set(rows.flatMap((r) => filesNamed(r.text)));
    const files = readdirSync(SRC).filter((name) => !isDir(join(SRC, name)) && !isTest(name));
    expect(files).toContain("editor.ts");
    expect(files.filter((f) => !named.has(f))).toEqual([]);
  });

  it("names no file that is not there", () => {
    const missing: string[] = [];
    for (const row of rows) {
      const folder = /^`(\w+)\/`$/.exec(row.path)?.[1] ?? "";
      for (const file of filesNamed(row.text)) {
        const found = [join(SRC, folder, file), join(SRC, file)].some((path) => {
          try {
            return statSync(path).isFile();
          } catch {
            return false;
          }
        });
        if (!found) missing.push(`${row.path}: ${file}`);
      }
    }
    expect(missing).toEqual([]);
  });
});

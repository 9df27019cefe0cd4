// SPDX-License-Identifier: EPL-2.0
// The TextMate grammars under the tokenizer VS Code itself uses (vscode-textmate on the Oniguruma WASM build):
// every keyword of the Xtext grammars is highlighted, no file of the repository has an illegal character, and
// known lines get the scopes a theme colours.

import assert from "node:assert/strict";
import * as fs from "node:fs";
import * as path from "node:path";
import { before, describe, test } from "node:test";
import * as oniguruma from "vscode-oniguruma";
import * as textmate from "vscode-textmate";

import { extensionRoot, readRepoFile, repoRoot, trackedFiles } from "./support";

type Language = "rei" | "vepl";

interface Token {
  text: string;
  scopes: string[];
}

const XTEXT: Record<Language, string> = {
  rei: "bundles/org.rei.dsl/src/main/java/org/rei/dsl/Rei.xtext",
  vepl: "cep/org.rei.vepl/src/main/java/org/rei/vepl/Vepl.xtext",
};

const grammars = new Map<Language, textmate.IGrammar>();

before(async () => {
  const wasm = fs.readFileSync(require.resolve("vscode-oniguruma/release/onig.wasm"));
  await oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
  const registry = new textmate.Registry({
    onigLib: Promise.resolve({
      createOnigScanner: (patterns: string[]) => new oniguruma.OnigScanner(patterns),
      createOnigString: (text: string) => new oniguruma.OnigString(text),
    }),
    loadGrammar: async (scopeName: string) => {
      const file = path.join(extensionRoot, "syntaxes", `${scopeName.replace(/^source\./, "")}.tmLanguage.json`);
      return textmate.parseRawGrammar(fs.readFileSync(file, "utf8"), file);
    },
  });
  for (const language of ["rei", "vepl"] as const) {
    const grammar = await registry.loadGrammar(`source.${language}`);
    assert.ok(grammar, `grammar source.${language} did not load`);
    grammars.set(language, grammar);
  }
});

/** Tokens per line, carrying the rule stack across lines as VS Code does (strings and comments span lines). */
function tokenize(language: Language, text: string): Token[][] {
  const grammar = grammars.get(language);
  assert.ok(grammar);
  let stack = textmate.INITIAL;
  return text.split(/\r?\n/).map((line) => {
    const result = grammar.tokenizeLine(line, stack);
    stack = result.ruleStack;
    return result.tokens.map((t) => ({ text: line.slice(t.startIndex, t.endIndex), scopes: t.scopes }));
  });
}

/** The innermost scope of the `occurrence`-th token that reads exactly `text` on line `line` (0-based). */
function scopeOf(lines: Token[][], line: number, text: string, occurrence = 0): string {
  const matches = lines[line].filter((t) => t.text === text);
  assert.ok(matches.length > occurrence, `no token "${text}" on line ${line}: ${JSON.stringify(lines[line])}`);
  const scopes = matches[occurrence].scopes;
  return scopes[scopes.length - 1];
}

/**
 * The quoted keywords of an Xtext grammar, read past its comments and its double-quoted import URIs so that a
 * word quoted in a comment ('signal' and 'rule' say ...) does not count.
 */
function xtextKeywords(source: string): Set<string> {
  const keywords = new Set<string>();
  for (let i = 0; i < source.length; ) {
    if (source.startsWith("//", i)) {
      i = source.indexOf("\n", i) === -1 ? source.length : source.indexOf("\n", i);
    } else if (source.startsWith("/*", i)) {
      i = source.indexOf("*/", i + 2) + 2;
    } else if (source[i] === "'" || source[i] === '"') {
      const quote = source[i];
      const end = source.indexOf(quote, i + 1);
      if (quote === "'") {
        keywords.add(source.slice(i + 1, end));
      }
      i = end + 1;
    } else {
      i++;
    }
  }
  return keywords;
}

function grammarKeywords(language: Language): { words: string[]; symbols: string[] } {
  const all = [...xtextKeywords(readRepoFile(XTEXT[language]))];
  const words = all.filter((k) => /^[A-Za-z]/.test(k));
  return { words, symbols: all.filter((k) => !words.includes(k)) };
}

/** Keywords that are keywords only in context (elsewhere 's' and 'x' are ordinary names): how to probe them. */
const PROBES: Record<Language, Record<string, string>> = {
  rei: { s: "goto F_1_1 within 90s", x: "room R size 6 x 4 {" },
  vepl: {},
};

const KEYWORD_SCOPE = /^(keyword|constant\.language)\./;
const SYMBOL_SCOPE = /^(punctuation|keyword\.operator)\./;

for (const language of ["rei", "vepl"] as const) {
  describe(`${language}.tmLanguage.json against ${path.basename(XTEXT[language])}`, () => {
    test("every word keyword of the Xtext grammar is highlighted as a keyword or language constant", () => {
      const { words } = grammarKeywords(language);
      assert.ok(words.length > 20, `only ${words.length} keywords read from ${XTEXT[language]}`);
      const missing = words.filter((keyword) => {
        const lines = tokenize(language, PROBES[language][keyword] ?? keyword);
        const token = lines[0].find((t) => t.text === keyword);
        return !token || !KEYWORD_SCOPE.test(token.scopes[token.scopes.length - 1]);
      });
      assert.deepEqual(missing, [], `keywords without a keyword scope in ${language}.tmLanguage.json`);
    });

    test("every symbol of the Xtext grammar is punctuation or an operator, never invalid", () => {
      const { symbols } = grammarKeywords(language);
      assert.ok(symbols.includes("{") && symbols.includes("["));
      const wrong = symbols.filter((symbol) => {
        const token = tokenize(language, symbol)[0].find((t) => t.text === symbol);
        return !token || !SYMBOL_SCOPE.test(token.scopes[token.scopes.length - 1]);
      });
      assert.deepEqual(wrong, [], `symbols not scoped as punctuation or operator in ${language}.tmLanguage.json`);
    });
  });
}

describe("the repository's .rei and .vepl files", () => {
  const files = trackedFiles("*.rei", "*.vepl");

  test("are all found (examples, patterns, test resources)", () => {
    const relative = files.map((f) => path.relative(repoRoot, f));
    for (const expected of ["examples/simple_navigation.rei", "cep/patterns/geometry.vepl"]) {
      assert.ok(relative.includes(expected), `${expected} not among ${relative.length} files`);
    }
    assert.ok(relative.some((f) => f.startsWith("cep/patterns/")) && relative.some((f) => f.startsWith("examples/")));
  });

  // Also the test resources with deliberate errors: none of them has a character the lexers reject.
  test("tokenize without a single invalid token", () => {
    const invalid: string[] = [];
    for (const file of files) {
      const language: Language = file.endsWith(".vepl") ? "vepl" : "rei";
      tokenize(language, fs.readFileSync(file, "utf8")).forEach((tokens, index) => {
        for (const token of tokens) {
          if (token.scopes.some((scope) => scope.startsWith("invalid"))) {
            invalid.push(`${path.relative(repoRoot, file)}:${index + 1}: ${JSON.stringify(token.text)}`);
          }
        }
      });
    }
    assert.deepEqual(invalid, []);
  });
});

describe("known lines", () => {
  test("simple_navigation.rei", () => {
    const lines = tokenize("rei", readRepoFile("examples/simple_navigation.rei"));
    assert.equal(scopeOf(lines, 0, "//"), "punctuation.definition.comment.rei");
    assert.ok(lines[0].every((t) => t.scopes.includes("comment.line.double-slash.rei")));
    assert.equal(scopeOf(lines, 2, "testcase"), "keyword.other.declaration.rei");
    assert.equal(scopeOf(lines, 2, "SimpleNavigation"), "entity.name.type.rei");
    // room Lab size 6 x 4 {
    assert.equal(scopeOf(lines, 3, "Lab"), "entity.name.type.rei");
    assert.equal(scopeOf(lines, 3, "size"), "keyword.other.rei");
    assert.equal(scopeOf(lines, 3, "6"), "constant.numeric.rei");
    assert.equal(scopeOf(lines, 3, "x"), "keyword.operator.dimension.rei");
    assert.equal(scopeOf(lines, 3, "{"), "punctuation.section.braces.begin.rei");
    // object table1 : Table on F_2_1
    assert.equal(scopeOf(lines, 4, "table1"), "variable.other.definition.rei");
    assert.equal(scopeOf(lines, 4, "Table"), "entity.name.type.rei");
    assert.equal(scopeOf(lines, 4, "F_2_1"), "source.rei", "a floor name is a plain name: no digits as numbers");
    // human walker trajectory [F_1_2 @ 0s, F_3_2 @ 6s, F_4_2 @ 9s] loop
    assert.equal(scopeOf(lines, 6, "walker"), "variable.other.definition.rei");
    assert.equal(scopeOf(lines, 6, "trajectory"), "keyword.other.declaration.rei");
    assert.equal(scopeOf(lines, 6, "@"), "keyword.operator.at.rei");
    assert.equal(scopeOf(lines, 6, "0"), "constant.numeric.rei");
    assert.equal(scopeOf(lines, 6, "s"), "keyword.other.unit.rei");
    assert.equal(scopeOf(lines, 6, "loop"), "keyword.other.rei");
    assert.equal(scopeOf(lines, 11, "goto"), "keyword.control.task.rei");
    // monitor { close 0.25 collision 0.01 maxHumanCollisions 1 }
    assert.equal(scopeOf(lines, 13, "0.25"), "constant.numeric.rei");
    assert.equal(scopeOf(lines, 13, "maxHumanCollisions"), "keyword.other.rei");
  });

  test("a room's map and a catalogue", () => {
    const office = tokenize("rei", readRepoFile("examples/l_shaped_office.rei"));
    // The map string spans lines: its inner lines are string, not '#' or '.' tokens.
    assert.equal(scopeOf(office, 5, "    #..#"), "string.quoted.double.rei");
    assert.equal(scopeOf(office, 3, "0.8"), "constant.numeric.rei");

    const catalogue = tokenize("rei", readRepoFile("examples/catalogues/office.rei"));
    // type Sofa : object box 1.1 x 0.8 x 0.8 mass 40 colour "#7A5230"
    assert.equal(scopeOf(catalogue, 4, "Sofa"), "entity.name.type.rei");
    assert.equal(scopeOf(catalogue, 4, "object"), "keyword.other.declaration.rei");
    assert.equal(scopeOf(catalogue, 4, "box"), "constant.language.shape.rei");
    assert.equal(scopeOf(catalogue, 4, "x", 1), "keyword.operator.dimension.rei");
    assert.equal(scopeOf(catalogue, 4, "#7A5230"), "string.quoted.double.rei");
    // robot type Burger : box 0.138 x 0.178 x 0.192 mass 1.0 colour "#202020"
    assert.equal(scopeOf(catalogue, 9, "Burger"), "entity.name.type.rei");
    assert.equal(scopeOf(catalogue, 9, "box"), "constant.language.shape.rei");
  });

  test("geometry.vepl", () => {
    const lines = tokenize("vepl", readRepoFile("cep/patterns/geometry.vepl"));
    const at = (prefix: string) => lines.findIndex((l) => l.map((t) => t.text).join("").startsWith(prefix));
    const query = at("queryEvent atomicFarFromObject()");
    assert.equal(scopeOf(lines, query, "atomicFarFromObject"), "entity.name.function.event.vepl");
    assert.equal(scopeOf(lines, query, "found"), "constant.language.query-event-kind.vepl");
    const pattern = at("  as (notAtomicFarFromObject -> atomicCloseToObject)");
    assert.equal(scopeOf(lines, pattern, "->"), "keyword.operator.followed-by.vepl");
    assert.equal(scopeOf(lines, pattern, "+"), "keyword.operator.quantifier.vepl");
    assert.equal(scopeOf(lines, pattern, "1000"), "constant.numeric.vepl");
    assert.equal(scopeOf(lines, pattern + 1, "immediate"), "constant.language.context.vepl");
    const signal = at("signal SIG_GEOM_FAR_TRANSIT_CLOSE");
    assert.equal(scopeOf(lines, signal, "SIG_GEOM_FAR_TRANSIT_CLOSE"), "variable.other.constant.signal.vepl");
    assert.equal(scopeOf(lines, signal, "-2"), "constant.numeric.vepl");
    assert.equal(scopeOf(lines, signal, "geometry"), "constant.language.zone-source.vepl");
    assert.equal(scopeOf(lines, signal, "FAR"), "constant.language.zone.vepl");
    const rule = at('rule "Robot goes from far to close"');
    assert.equal(scopeOf(lines, rule, "rule"), "keyword.other.declaration.vepl");
    assert.equal(scopeOf(lines, rule, "Robot goes from far to close"), "string.quoted.double.vepl");
    assert.equal(scopeOf(lines, rule, "emits"), "keyword.other.vepl");
    // A rule's emits list continues on the next line.
    const split = at('rule "Robot goes from far straight into collision"');
    assert.equal(scopeOf(lines, split + 1, "emits"), "keyword.other.vepl");
  });

  test("a character no lexer token starts with is invalid; an action block's content is not", () => {
    assert.equal(scopeOf(tokenize("rei", "    robot r : Waffle on F_0_0 ;"), 0, ";"), "invalid.illegal.character.rei");
    assert.equal(scopeOf(tokenize("vepl", "signal S utility 1 $"), 0, "$"), "invalid.illegal.character.vepl");

    const lines = tokenize("vepl", readRepoFile("cep/org.rei.vepl/src/test/resources/invalid/action-block.vepl"));
    const inBlock = lines.findIndex((l) => l.some((t) => t.text.includes("val signal = new Signal(")));
    assert.ok(inBlock > 0);
    assert.ok(lines[inBlock].every((t) => t.scopes.includes("meta.block.action.vepl")));
    // After the block's closing brace, the rule is over and nothing is left inside it.
    const after = tokenize("vepl", "rule r on e {\n  a; b > c { d }\n}\nsignal S utility 1\n");
    assert.ok(after[1].every((t) => t.scopes.includes("meta.block.action.vepl") && !t.scopes.some((s) => s.startsWith("invalid"))));
    assert.equal(scopeOf(after, 3, "S"), "variable.other.constant.signal.vepl");
    assert.ok(!after[3].some((t) => t.scopes.includes("meta.block.action.vepl")));
  });
});

/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.ide.tests;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import java.util.TreeSet;
import java.util.concurrent.ExecutionException;

import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.xtext.testing.AbstractLanguageServerTest;
import org.junit.jupiter.api.Assertions;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.rei.vepl.runtime.MissionEvent;
import org.rei.vepl.validation.KnownQueries;

/**
 * VEPL as an editor sees it: requests go to Xtext's language server (the one the server jar runs), which loads
 * the language through META-INF/services as the jar does. Positions are 0-based, as in LSP. (Assertions is
 * qualified: the base class has an assertEquals of its own.)
 */
class VeplLanguageServerTest extends AbstractLanguageServerTest {

	/** The queries of the workspace's own queries/ folder that are not default queries. */
	private static final List<String> OWN = List.of("laserBlinded", "robotWaving");

	private static final String PATTERNS = """
			queryEvent closeFound as robotClose found
			queryEvent nearFound as robotNear found
			atomicEvent started as mission TASK_STRT
			complexEvent closeInTask() { as started -> closeFound -> farLost }
			signal SIG_CLOSE_IN_TASK utility -2
			rule closeInTask on closeInTask emits SIG_CLOSE_IN_TASK
			""";

	private boolean initialized;

	VeplLanguageServerTest() {
		super("vepl");
	}

	/** In target/, not in the module folder; above it lies the repository's queries/ folder. */
	@BeforeEach
	void workspaceInTarget() {
		root = Path.of("target", "lsp-workspace").toAbsolutePath().toFile();
	}

	@TempDir
	Path outside;

	/**
	 * A queries/ folder of the workspace's own, the nearest above its files: its queries (one of them also a
	 * default) come on top of the defaults, as the monitor loads {@code --queries DIR} beside them.
	 */
	private void writeQueries() {
		writeFile("queries/state.drl", "query robotClose(String robot)\nend\nquery robotWaving(String robot)\nend\n");
		writeFile("queries/laser.drl", "query laserBlinded(String robot)\nend\n");
	}

	/** The default queries and {@code own}, sorted, as the message lists them and completion offers them. */
	private static List<String> defaultsAnd(List<String> own) {
		TreeSet<String> all = new TreeSet<>(KnownQueries.inFolder(repositoryQueries()));
		all.addAll(own);
		return List.copyOf(all);
	}

	/** A workspace outside the repository (a user's), with no queries/ folder above it. */
	private void workspaceOutside() {
		root = outside.toFile();
		for (Path dir = outside; dir != null; dir = dir.getParent()) {
			assertFalse(Files.isDirectory(dir.resolve("queries")), "the test needs no queries/ above " + outside);
		}
	}

	@Test
	void diagnosticsPointAtTheWrongNameAndListTheKnownQueries() {
		writeQueries();
		String uri = openFile("patterns/p.vepl", PATTERNS);
		Assertions.assertEquals(List.of(
				"[1:24-1:33] org.rei.vepl.unknownQuery Unknown query 'robotNear': the loaded queries are "
						+ String.join(", ", defaultsAnd(OWN)),
				"[2:31-2:40] org.rei.vepl.unknownMissionEvent Unknown mission event 'TASK_STRT': one of BEGIN, "
						+ "TASK_START, TASK_SUCCESS, TASK_FAIL, END, " + String.join(", ", MissionEvent.FAULT_EVENTS),
				"[3:57-3:64] " + org.eclipse.xtext.diagnostics.Diagnostic.LINKING_DIAGNOSTIC
						+ " Couldn't resolve reference to Event 'farLost'."),
				diagnostics(uri));
	}

	@Test
	void aSyntaxErrorIsReportedOnTheOffendingToken() {
		String uri = openFile("p.vepl", "queryEvent closeFound as robotClose fund\n");
		Assertions.assertEquals(List.of("[0:36-0:40] " + org.eclipse.xtext.diagnostics.Diagnostic.SYNTAX_DIAGNOSTIC
				+ " no viable alternative at input 'fund'"), diagnostics(uri));
	}

	@Test
	void aFileNestedTooDeepGetsOneErrorOnTheFirstBracketTooManyAndTheNextFileIsStillChecked() throws Exception {
		String deep = "queryEvent a as robotFar found\n/* ((((( */ complexEvent c() { as " + "(".repeat(3_000) + "a"
				+ ")".repeat(3_000) + " }\n";
		String deepUri = openFile("deep.vepl", deep);
		// the brace is level 1: the 100th '(' is one too many, 0-based column 12 + 22 + 99
		Assertions.assertEquals(List.of("[1:133-1:134] org.rei.vepl.tooDeep Brackets nested deeper than 100 levels: "
				+ "the file is not parsed (no pattern needs that many)"), diagnostics(deepUri));
		// completion answers: the refused file's node model has the entry rule at its root, as editor services
		// expect (without it the request failed with "No Root Parser Rule found")
		assertFalse(labels(deepUri, new Position(1, 133)).isEmpty());
		String uri = openFile("next.vepl", "queryEvent nearFound as robotNear found\n");
		Assertions.assertEquals(1, diagnostics(uri).size(), () -> diagnostics(uri).toString());
		assertTrue(diagnostics(uri).get(0).startsWith("[0:24-0:33] org.rei.vepl.unknownQuery"), diagnostics(uri)::toString);
	}

	@Test
	void aFileThatDeclaresNothingAndANameTwoFilesOfAFolderDeclareAreErrors() {
		writeFile("patterns/one.vepl", "signal S\nsignal T\n"); // before the server starts: in its index
		writeFile("elsewhere/three.vepl", "signal T\n"); // another folder: not loaded together with patterns/
		Assertions.assertEquals(List.of("[0:0-0:0] org.rei.vepl.emptyFile The file declares no event, signal or rule "
				+ "(queryEvent, atomicEvent, complexEvent, signal, rule)"), diagnostics(openFile("empty.vepl", "// nothing\n")));
		String uri = openFile("patterns/two.vepl", "signal T\n");
		Assertions.assertEquals(List.of("[0:7-0:8] org.rei.vepl.duplicateName Duplicate name 'T': signal T is also "
				+ "declared in one.vepl on line 2 (names are global over the files loaded together)"), diagnostics(uri));
	}

	@Test
	void aQueryIsCompletedWithTheQueriesTheValidatorAccepts() throws Exception {
		writeQueries();
		String text = "queryEvent b as ro found\nqueryEvent a as \n";
		String uri = openFile("p.vepl", text);
		Assertions.assertEquals(defaultsAnd(OWN), labels(uri, after(text, "queryEvent a as ")));
		Assertions.assertEquals(List.of("robotClose", "robotFar", "robotInCollision", "robotWaving"),
				labels(uri, after(text, "queryEvent b as ro")));
	}

	@Test
	void aFileOutsideTheRepositoryKnowsTheDefaultQueries() throws Exception {
		workspaceOutside();
		String uri = openFile("patterns/p.vepl", "queryEvent nearFound as robotNear found\n");
		Assertions.assertEquals(List.of("[0:24-0:33] org.rei.vepl.unknownQuery Unknown query 'robotNear': the "
				+ "loaded queries are " + String.join(", ", defaultsAnd(List.of()))), diagnostics(uri));
		String text = "queryEvent a as \n"; // a file of its own: unfinished, it has a syntax error
		Assertions.assertEquals(defaultsAnd(List.of()), labels(openFile("patterns/q.vepl", text), after(text, "as ")));
	}

	@Test
	void aFileOutsideTheRepositoryWithItsOwnQueriesKnowsTheDefaultsAndItsOwn() throws Exception {
		workspaceOutside();
		writeQueries();
		String uri = openFile("patterns/p.vepl", "queryEvent closeFound as robotClose found\n"
				+ "queryEvent wave as robotWaving found\nqueryEvent nearFound as robotNear found\n");
		Assertions.assertEquals(List.of("[2:24-2:33] org.rei.vepl.unknownQuery Unknown query 'robotNear': the "
				+ "loaded queries are " + String.join(", ", defaultsAnd(OWN))), diagnostics(uri));
		String text = "queryEvent a as \n";
		Assertions.assertEquals(defaultsAnd(OWN), labels(openFile("patterns/q.vepl", text), after(text, "as ")));
	}

	@Test
	void aFileOfTheRepositoryIsCompletedWithTheQueriesTheMonitorPackages() throws Exception {
		String text = "queryEvent a as \n";
		String uri = openFile("p.vepl", text);
		List<String> offered = labels(uri, after(text, "as "));
		Assertions.assertEquals(List.copyOf(KnownQueries.inFolder(repositoryQueries())), offered);
		assertTrue(offered.containsAll(List.of("robotClose", "robotFar", "robotInCollision")), offered.toString());
	}

	@Test
	void aMissionEventIsCompletedWithTheMissionTopicsEvents() throws Exception {
		String text = "atomicEvent b as mission TASK_S\natomicEvent a as mission \n";
		String uri = openFile("p.vepl", text);
		List<String> events = new java.util.ArrayList<>(List.of("BEGIN", "END", "TASK_FAIL", "TASK_START",
				"TASK_SUCCESS"));
		events.addAll(MissionEvent.FAULT_EVENTS); // the fault window edges (FAULT_LASER_BLACKOUT_BEGIN, ...)
		java.util.Collections.sort(events);
		Assertions.assertEquals(events, labels(uri, after(text, "atomicEvent a as mission ")));
		Assertions.assertEquals(List.of("TASK_START", "TASK_SUCCESS"), labels(uri, after(text, "mission TASK_S")));
	}

	@Test
	void eventsOfThisFileAndOfTheOtherFilesAreCompletedWhereAnEventStands() throws Exception {
		writeFile("other.vepl", "queryEvent farLost as robotFar lost\n");
		String text = """
				queryEvent closeFound as robotClose found
				atomicEvent started as mission TASK_START
				complexEvent closeInTask() { as started ->  }
				signal SIG_CLOSE_IN_TASK
				rule inTask on  emits SIG_CLOSE_IN_TASK
				rule again on started emits\s
				""";
		String uri = openFile("p.vepl", text);
		// not closeInTask itself: a complex event that refers to itself is an error
		Assertions.assertEquals(List.of("closeFound", "farLost", "started", "NOT", "!", "("),
				labels(uri, after(text, "as started -> ")));
		Assertions.assertEquals(List.of("closeFound", "closeInTask", "farLost", "started"),
				labels(uri, after(text, "inTask on ")));
		Assertions.assertEquals(List.of("SIG_CLOSE_IN_TASK"), labels(uri, after(text, "started emits ")));
	}

	@Test
	void keywordsAreCompletedWhereADeclarationOrTheHeaderMayStart() throws Exception {
		String text = "\nqueryEvent a as robotFar lost\n\n";
		String uri = openFile("p.vepl", text);
		Assertions.assertEquals(List.of("atomicEvent", "complexEvent", "import", "import-queries", "package",
				"queryEvent", "rule", "signal"), labels(uri, new Position(0, 0)));
		Assertions.assertEquals(List.of("atomicEvent", "complexEvent", "queryEvent", "rule", "signal"),
				labels(uri, new Position(2, 0)));
	}

	@Test
	void aUseOfAQueryEventHoversItsDeclaration() throws Exception {
		String uri = openFile("p.vepl", PATTERNS);
		Position onUse = after(PATTERNS, "as started -> c");
		String hover = languageServer.hover(new HoverParams(new TextDocumentIdentifier(uri), onUse)).get()
				.getContents().getRight().getValue();
		assertTrue(hover.contains("Query event closeFound") && hover.contains("`robotClose` appears"), hover);
	}

	/** Starts the server on the workspace and opens one file as an editor does; its URI. */
	private String openFile(String path, String text) {
		if (!initialized) {
			initialize();
			initialized = true;
		}
		String uri = writeFile(path, text);
		open(uri, text);
		return uri;
	}

	/** The file's diagnostics, each as {@code [line:column-line:column] code message}, first position first. */
	private List<String> diagnostics(String uri) {
		return getDiagnostics().get(uri).stream()
				.sorted(Comparator.comparing((Diagnostic d) -> d.getRange().getStart().getLine())
						.thenComparing(d -> d.getRange().getStart().getCharacter()))
				.map(d -> "[" + at(d.getRange().getStart()) + "-" + at(d.getRange().getEnd()) + "] "
						+ d.getCode().getLeft() + " " + d.getMessage().getLeft())
				.toList();
	}

	private static String at(Position p) {
		return p.getLine() + ":" + p.getCharacter();
	}

	private List<String> labels(String uri, Position at) throws InterruptedException, ExecutionException {
		var result = languageServer.completion(new CompletionParams(new TextDocumentIdentifier(uri), at)).get();
		List<CompletionItem> items = result.isLeft() ? result.getLeft() : result.getRight().getItems();
		return items.stream().map(CompletionItem::getLabel).toList();
	}

	/** The position just after the first occurrence of {@code snippet}. */
	private static Position after(String text, String snippet) {
		int end = text.indexOf(snippet) + snippet.length();
		String before = text.substring(0, end);
		int line = (int) before.chars().filter(c -> c == '\n').count();
		return new Position(line, end - before.lastIndexOf('\n') - 1);
	}

	/** The repository's queries/ folder, the one the monitor packages. */
	private static Path repositoryQueries() {
		for (Path dir = Path.of("").toAbsolutePath(); dir != null; dir = dir.getParent()) {
			if (Files.isDirectory(dir.resolve("queries"))) {
				return dir.resolve("queries");
			}
		}
		throw new IllegalStateException("no queries/ folder above " + Path.of("").toAbsolutePath());
	}
}

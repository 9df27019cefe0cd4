// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.tests;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Stream;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IFolder;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.core.runtime.preferences.IEclipsePreferences;
import org.eclipse.core.runtime.preferences.InstanceScope;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.ITextViewer;
import org.eclipse.jface.text.Region;
import org.eclipse.jface.text.contentassist.ICompletionProposal;
import org.eclipse.jface.text.hyperlink.IHyperlink;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.jface.wizard.WizardDialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.StyleRange;
import org.eclipse.swt.custom.StyledText;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.IPageLayout;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.dialogs.WizardNewFileCreationPage;
import org.eclipse.ui.handlers.IHandlerService;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.texteditor.ITextEditor;
import org.eclipse.ui.views.contentoutline.IContentOutlinePage;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.rei.eclipse.ReiIds;
import org.rei.eclipse.commands.Generator;
import org.rei.eclipse.commands.ProcessResult;
import org.rei.eclipse.editor.CompletionProcessor;
import org.rei.eclipse.editor.DefinitionHyperlinkDetector;
import org.rei.eclipse.editor.LspHover;
import org.rei.eclipse.lsp.Jars;
import org.rei.eclipse.wizards.NewTestCaseWizard;

/**
 * The plug-in in a real workbench with REI's real language server and generator: what a test engineer sees when
 * they open, break, fix and generate a test case. The first test opens the first file: its time to the first
 * markers includes the language server's start.
 */
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class ReiEditorWorkbenchTest {
	/** The first markers wait for the server's start (a JVM and Xtext) on a busy two-core machine. */
	private static final long SERVER_MILLIS = 90_000;
	private static final List<String> ARTIFACTS = List.of("animation.json", "mission.xml", "monitor.json",
			"world.json", "world.sdf");

	private static IProject project;
	private static String example;

	@BeforeAll
	static void workspace() throws Exception {
		project = Workbench.project("rei-ui-test");
		example = Files.readString(Path.of(System.getProperty("rei.root"), "examples", "simple_navigation.rei"));
		PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell().setSize(1280, 800);
	}

	@Test
	@Order(1)
	void anInvalidTestCaseShowsItsMarkersAndFixingItClearsThem() throws Exception {
		assertTrue(example.contains(": Table on F_2_1"), "the example still places its table on F_2_1");
		IFile file = Workbench.write(project, "broken.rei", example.replace(": Table on F_2_1", ": Tabel on F_2_1"));
		long opened = System.nanoTime();
		IEditorPart part = IDE.openEditor(Workbench.page(), file);
		assertEquals("org.eclipse.ui.genericeditor.GenericEditor", part.getSite().getId());
		ITextEditor editor = (ITextEditor) part;

		Workbench.waitUntil(() -> Workbench.markers(file).stream()
				.anyMatch(marker -> marker.getAttribute(IMarker.LINE_NUMBER, -1) == 5
						&& marker.getAttribute(IMarker.SEVERITY, -1) == IMarker.SEVERITY_ERROR
						&& marker.getAttribute(IMarker.MESSAGE, "").contains("Tabel")),
				SERVER_MILLIS, () -> "an error on line 5 naming Tabel; markers: " + Workbench.describe(Workbench.markers(file)));
		long firstMarkers = (System.nanoTime() - opened) / 1_000_000;
		System.out.println("REI UI test: first markers " + firstMarkers + " ms after opening the file");
		IMarker marker = Workbench.markers(file).get(0);
		IDocument document = Workbench.documentOf(editor);
		int typo = document.get().indexOf("Tabel");
		assertEquals(typo, marker.getAttribute(IMarker.CHAR_START, -1), "the marker starts at the unknown name");
		assertEquals(typo + "Tabel".length(), marker.getAttribute(IMarker.CHAR_END, -1));

		Workbench.page().showView(IPageLayout.ID_PROBLEM_VIEW);
		Workbench.page().showView(IPageLayout.ID_OUTLINE);
		Workbench.page().activate(editor);
		Workbench.flush(1500);
		Workbench.screenshot("eclipse-markers.png");

		document.replace(typo, "Tabel".length(), "Table");
		Workbench.waitUntil(() -> Workbench.markers(file).isEmpty(), SERVER_MILLIS,
				() -> "no markers once fixed; markers: " + Workbench.describe(Workbench.markers(file)));
		editor.doSave(null);
		Workbench.page().closeEditor(editor, false);
	}

	@Test
	@Order(2)
	void generateArtifactsWritesWhatTheGeneratorWritesFromTheCommandLine() throws Exception {
		IFile file = Workbench.write(project, "simple.rei", example);
		ITextEditor editor = (ITextEditor) IDE.openEditor(Workbench.page(), file);
		Workbench.flush(200);

		PlatformUI.getWorkbench().getService(IHandlerService.class).executeCommand(ReiIds.GENERATE_COMMAND, null);
		Job.getJobManager().join(ReiIds.JOB_FAMILY, null);
		Workbench.flush(200);

		IFolder output = project.getFolder("simple-artifacts");
		assertTrue(output.exists(), "the workspace shows the output folder");
		for (String artifact : ARTIFACTS) {
			assertTrue(output.getFile(artifact).exists(), artifact + " is in the workspace");
		}
		Path reference = Files.createTempDirectory("rei-generate");
		Path testCase = file.getLocation().toFile().toPath();
		ProcessResult cli = ProcessResult.run(List.of(Jars.java(), "-jar", Jars.locate(Jars.GENERATOR).toString(),
				"generate", testCase.toString(), "-o", reference.toString()), testCase.getParent().toFile(), 120, null);
		assertEquals(0, cli.exitCode(), cli.output());
		Path written = Generator.outputFor(testCase);
		assertEquals(ARTIFACTS, names(reference));
		assertEquals(ARTIFACTS, names(written));
		for (String artifact : ARTIFACTS) {
			assertArrayEquals(Files.readAllBytes(reference.resolve(artifact)), Files.readAllBytes(written.resolve(artifact)),
					artifact + " is byte for byte what rei generate writes");
		}
		Workbench.page().closeEditor(editor, false);
	}

	@Test
	@Order(3)
	void theNewTestCaseWizardsTemplateIsValid() throws Exception {
		IFile file = Workbench.write(project, "fresh_case.rei", NewTestCaseWizard.contents("fresh_case.rei") + "oops\n");
		ITextEditor editor = (ITextEditor) IDE.openEditor(Workbench.page(), file);
		Workbench.waitUntil(() -> !Workbench.markers(file).isEmpty(), SERVER_MILLIS,
				() -> "a syntax error for the text after the test case");
		IDocument document = Workbench.documentOf(editor);
		document.set(NewTestCaseWizard.contents("fresh_case.rei"));
		Workbench.waitUntil(() -> Workbench.markers(file).isEmpty(), SERVER_MILLIS,
				() -> "the template is valid; markers: " + Workbench.describe(Workbench.markers(file)));
		assertTrue(document.get().contains("testcase FreshCase {"));
		Workbench.page().closeEditor(editor, false);
	}

	@Test
	@Order(4)
	void completionHoverDefinitionAndOutlineComeFromTheServer() throws Exception {
		IFile file = Workbench.write(project, "features.rei", example);
		ITextEditor editor = (ITextEditor) IDE.openEditor(Workbench.page(), file);
		ITextViewer viewer = Workbench.viewerOf(editor);
		IDocument document = Workbench.documentOf(editor);
		int reference = document.get().indexOf("goto F_4_0") + "goto ".length();

		ICompletionProposal[][] proposals = new ICompletionProposal[1][];
		Workbench.waitUntil(() -> {
			proposals[0] = new CompletionProcessor().computeCompletionProposals(viewer, reference + "F_4".length());
			return Stream.of(proposals[0]).anyMatch(p -> p.getDisplayString().startsWith("F_4_0"));
		}, SERVER_MILLIS, () -> "floor names after 'goto F_4'; got " + labels(proposals[0]));
		assertTrue(Stream.of(proposals[0]).allMatch(p -> p.getDisplayString().startsWith("F_4")),
				"only floors that start with the typed prefix: " + labels(proposals[0]));

		String hover = new LspHover().getHoverInfo(viewer, new Region(reference + 1, 0));
		assertNotNull(hover, "a hover on a floor reference");
		assertTrue(hover.contains("Floor F_4_0: x 4..5 m"), hover);
		assertFalse(hover.contains("**"), "markdown marks are not shown: " + hover);

		IHyperlink[] links = new DefinitionHyperlinkDetector().detectHyperlinks(viewer, new Region(reference + 1, 0), false);
		assertNotNull(links, "a definition for the floor reference");
		assertEquals(reference, links[0].getHyperlinkRegion().getOffset());
		assertEquals("F_4_0".length(), links[0].getHyperlinkRegion().getLength());

		assertNotNull(editor.getAdapter(IContentOutlinePage.class), "the editor has an outline");

		// colouring: a keyword is bold, the digit of a name is not coloured as a number
		StyledText text = viewer.getTextWidget();
		StyleRange keyword = text.getStyleRangeAtOffset(document.get().indexOf("testcase"));
		assertNotNull(keyword, "'testcase' is coloured");
		assertEquals(SWT.BOLD, keyword.fontStyle & SWT.BOLD);
		StyleRange digit = text.getStyleRangeAtOffset(document.get().indexOf("table1") + "table".length());
		assertTrue(digit == null || digit.foreground == null || digit.foreground.equals(text.getForeground()),
				"the 1 of table1 is part of a name: " + digit);
		Workbench.page().closeEditor(editor, false);
	}

	@Test
	@Order(5)
	void savingATestCaseGeneratesItsArtifactsWhenThePreferenceIsOn() throws Exception {
		IEclipsePreferences preferences = InstanceScope.INSTANCE.getNode(ReiIds.PLUGIN);
		IFile file = Workbench.write(project, "on_save.rei", example);
		ITextEditor editor = (ITextEditor) IDE.openEditor(Workbench.page(), file);
		IFolder output = project.getFolder("on_save-artifacts");
		try {
			preferences.putBoolean(ReiIds.PREF_GENERATE_ON_SAVE, true);
			IDocument document = Workbench.documentOf(editor);
			document.replace(document.get().indexOf("F_0_3"), "F_0_3".length(), "F_1_3");
			editor.doSave(null);
			Workbench.waitUntil(() -> output.getFile("world.json").exists(), SERVER_MILLIS,
					() -> "on_save-artifacts/world.json after saving");
			assertTrue(Files.readString(output.getFile("world.json").getLocation().toFile().toPath()).contains("shelf1"));
		} finally {
			preferences.putBoolean(ReiIds.PREF_GENERATE_ON_SAVE, false);
			Workbench.page().closeEditor(editor, false);
		}
	}

	/** The whole of rei run (router, simulation, monitor, evaluation) through the user's REI installation. */
	@Test
	@Order(6)
	void runTestCaseRunsReiRunAndWritesTheReport() throws Exception {
		IEclipsePreferences preferences = InstanceScope.INSTANCE.getNode(ReiIds.PLUGIN);
		preferences.put(ReiIds.PREF_LAUNCHER, Path.of(System.getProperty("rei.root"), "rei").toString());
		preferences.putBoolean(ReiIds.PREF_OPEN_REPORT, false); // no browser window on the build machine
		IFile file = Workbench.write(project, "run_me.rei", example);
		ITextEditor editor = (ITextEditor) IDE.openEditor(Workbench.page(), file);
		try {
			PlatformUI.getWorkbench().getService(IHandlerService.class).executeCommand(ReiIds.RUN_COMMAND, null);
			Workbench.waitUntil(() -> Job.getJobManager().find(ReiIds.JOB_FAMILY).length == 0, 300_000,
					() -> "rei run to end");
			IFolder run = project.getFolder("run_me-run");
			assertTrue(run.getFile("report.html").exists(), "report.html in the workspace");
			assertTrue(run.getFile("summary.json").exists(), "summary.json in the workspace");
		} finally {
			preferences.remove(ReiIds.PREF_LAUNCHER);
			preferences.remove(ReiIds.PREF_OPEN_REPORT);
			Workbench.page().closeEditor(editor, false);
		}
	}

	@Test
	@Order(7)
	void theNewTestCaseWizardCreatesTheFileAndOpensIt() throws Exception {
		NewTestCaseWizard wizard = new NewTestCaseWizard();
		wizard.init(PlatformUI.getWorkbench(), new StructuredSelection(project));
		WizardDialog dialog = new WizardDialog(PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell(), wizard);
		dialog.create();
		try {
			((WizardNewFileCreationPage) wizard.getPage("testCase")).setFileName("from-the wizard.rei");
			assertTrue(wizard.performFinish());
		} finally {
			dialog.close();
		}
		IFile created = project.getFile("from-the wizard.rei");
		assertTrue(created.exists(), "the wizard created the file");
		assertTrue(Files.readString(created.getLocation().toFile().toPath()).contains("testcase FromTheWizard {"));
		IEditorPart active = Workbench.page().getActiveEditor();
		assertEquals("from-the wizard.rei", active.getEditorInput().getName(), "and opened it");
		Workbench.page().closeEditor(active, false);
	}

	/**
	 * A room from an occupancy map: the language server and the generator read the map (its YAML with SnakeYAML,
	 * its image) beside the file, inside the plug-in as on the command line.
	 */
	@Test
	@Order(8)
	void aMapRoomIsCheckedAgainstItsMapAndGeneratesTheMapCopy() throws Exception {
		Path maps = Path.of(System.getProperty("rei.root"), "examples", "maps");
		String testCase = Files.readString(maps.resolve("two_rooms.rei"));
		assertTrue(testCase.contains("occupancy \"two_rooms.yaml\""), "the example still names its map");
		Workbench.write(project, "two_rooms.yaml", Files.readString(maps.resolve("two_rooms.yaml")));
		byte[] image = Files.readAllBytes(maps.resolve("two_rooms.pgm"));
		Workbench.write(project, "two_rooms.pgm", image);
		IFile file = Workbench.write(project, "map_room.rei", testCase.replace("\"two_rooms.yaml\"", "\"no_such_map.yaml\""));
		ITextEditor editor = (ITextEditor) IDE.openEditor(Workbench.page(), file);
		try {
			IDocument document = Workbench.documentOf(editor);
			int map = document.get().indexOf("\"no_such_map.yaml\"");
			Workbench.waitUntil(() -> Workbench.markers(file).stream()
					.anyMatch(marker -> marker.getAttribute(IMarker.CHAR_START, -1) == map
							&& marker.getAttribute(IMarker.SEVERITY, -1) == IMarker.SEVERITY_ERROR
							&& marker.getAttribute(IMarker.MESSAGE, "").contains("no_such_map.yaml")),
					SERVER_MILLIS, () -> "an error at the map's name; markers: " + Workbench.describe(Workbench.markers(file)));

			document.replace(map, "\"no_such_map.yaml\"".length(), "\"two_rooms.yaml\"");
			Workbench.waitUntil(() -> Workbench.markers(file).isEmpty(), SERVER_MILLIS,
					() -> "no markers once the map exists; markers: " + Workbench.describe(Workbench.markers(file)));
			editor.doSave(null);

			PlatformUI.getWorkbench().getService(IHandlerService.class).executeCommand(ReiIds.GENERATE_COMMAND, null);
			Job.getJobManager().join(ReiIds.JOB_FAMILY, null);
			Workbench.flush(200);
			Path written = Generator.outputFor(file.getLocation().toFile().toPath());
			assertArrayEquals(image, Files.readAllBytes(written.resolve("map.pgm")), "the map's image, copied byte for byte");
			assertTrue(Files.readString(written.resolve("map.yaml")).contains("image: map.pgm"),
					"the copy's YAML names the copied image");
			String world = Files.readString(written.resolve("world.json"));
			assertTrue(world.contains("\"W_map_"), "the map's obstacles are walls of the world");
		} finally {
			Workbench.page().closeEditor(editor, false);
		}
	}

	private static List<String> names(Path folder) throws IOException {
		try (Stream<Path> files = Files.list(folder)) {
			return files.map(path -> path.getFileName().toString()).sorted().toList();
		}
	}

	private static String labels(ICompletionProposal[] proposals) {
		return proposals == null ? "nothing" : Arrays.toString(Stream.of(proposals).map(ICompletionProposal::getDisplayString).toArray());
	}
}

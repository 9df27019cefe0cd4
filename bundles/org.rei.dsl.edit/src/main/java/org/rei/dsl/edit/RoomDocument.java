/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.IGrammarAccess;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.formatting2.regionaccess.ITextReplacement;
import org.eclipse.xtext.ide.serializer.IChangeSerializer;
import org.eclipse.xtext.ide.serializer.IEmfResourceChange;
import org.eclipse.xtext.ide.serializer.ITextDocumentChange;
import org.eclipse.xtext.resource.IResourceFactory;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.scoping.IScopeProvider;
import org.rei.context.TestCase;
import org.rei.dsl.edit.diagram.Diagram;
import org.rei.dsl.edit.diagram.DiagramBuilder;
import org.rei.dsl.edit.diagram.Palette;
import org.rei.dsl.edit.diagram.PaletteType;
import org.rei.dsl.edit.serializer.TangledListException;

import com.google.inject.Injector;

/**
 * A test case open in the room editor: its text, the model parsed from it, and the validators' findings; edits
 * change the model and come back as text edits.
 * <p>
 * <b>Design.</b> An edit is applied to the EMF model while Xtext's {@link IChangeSerializer} records it; the
 * serializer turns the recorded change into the smallest text replacements it can find, from the node model of the
 * parsed text. That is the grammar's own serializer at work, so whatever it writes is what the parser reads, and it
 * touches only the statements that changed. Written text is laid out by
 * {@link org.rei.dsl.edit.serializer.RoomLayoutFormatter} (a new statement on its own line, indented like its
 * neighbours) and {@link org.rei.dsl.edit.serializer.RoomPartialSerializer} closes three gaps of Xtext's partial
 * serializer that would otherwise rewrite a whole room. Every result is parsed again and must give a model equal to
 * the edited one (EMF's EqualityHelper), else the edit fails and the document keeps its text: a diagram never saves
 * a file that means something else than what it shows. The new text is validated by the language's validators;
 * their findings name the diagram element they are on.
 * <p>
 * <b>Preserved</b>: everything outside the changed statements keeps its characters - comments, blank lines,
 * indentation, line ends, statement order, a map's drawing, the spelling of numbers ({@code 60 s}). A moved object or
 * goal keeps its line but for the changed name; a new yaw or timeout is appended to its line. <b>Not preserved</b>: a
 * statement that is written anew (an added or moved goal, a trajectory whose points were added or removed) is
 * spelled the serializer's way ({@code 6s}); a deleted statement takes the comment lines right above it along (a
 * moved one carries them to its new place).
 * <p>
 * <b>Refused</b> ({@link EditRefusedException}, nothing changes): what the text cannot express - unknown names, a
 * name that is taken or not a name, floors and walls of a grid or map room (they are derived from its size or
 * drawing), removing a floor something stands on or a goal names, deleting the robot. What the text can express but
 * the rules forbid (two objects on one floor, a goal behind a wall) is applied and reported by the validators, as in
 * the text editor.
 * <p>
 * <b>Undo</b> applies the inverse of the text edits (computed from the edits and the text they replaced), so undo
 * and redo are minimal text edits too, and a client that mirrors the text stays in step.
 * <p>
 * Not thread-safe: one document per editor session, used from one thread at a time.
 */
public final class RoomDocument {

	private record Version(String text, XtextResource resource, List<ValidationIssue> issues) {
		TestCase testCase() {
			return resource.getContents().isEmpty() || !(resource.getContents().get(0) instanceof TestCase testCase)
					? null
					: testCase;
		}
	}

	private record Step(List<TextEdit> forward, List<TextEdit> backward) {
	}

	/** Where the time of the last {@link #apply} went, in milliseconds (for the benchmark and a server's log). */
	record Timings(long serialize, long parse, long validate, long compare) {
	}

	private long serializeNanos;
	private long parseNanos;
	private long validateNanos;
	private long compareNanos;

	private final Injector injector;
	private final URI uri;
	private final Set<String> reservedWords;
	private final Deque<Step> undo = new ArrayDeque<>();
	private final Deque<Step> redo = new ArrayDeque<>();
	private Version current;
	private Version paletteOf;
	private List<PaletteType> palette;

	private RoomDocument(Injector injector, URI uri, String text) {
		this.injector = injector;
		this.uri = uri;
		this.reservedWords = reservedWords(injector.getInstance(IGrammarAccess.class));
		this.current = parse(text);
		if (current.testCase() == null) {
			throw new IllegalArgumentException(uri + " is not a test case ('testcase NAME { room ... }')");
		}
	}

	/** Opens a file; catalogue imports are read relative to it. */
	public static RoomDocument open(Path file) throws IOException {
		Path absolute = file.toAbsolutePath().normalize();
		return of(URI.createFileURI(absolute.toString()), Files.readString(absolute, StandardCharsets.UTF_8));
	}

	/** A text as if it were the file at {@code uri} (which should end in .rei; imports resolve against it). */
	public static RoomDocument of(URI uri, String text) {
		return new RoomDocument(RoomEditSetup.injector(), uri, text);
	}

	public URI uri() {
		return uri;
	}

	public String text() {
		return current.text();
	}

	/** The model of the current text; read it, change it only through {@link #apply}. */
	public TestCase model() {
		return current.testCase();
	}

	public List<ValidationIssue> issues() {
		return current.issues();
	}

	public Diagram diagram() {
		return DiagramBuilder.of(model());
	}

	/** The catalogue types the text can name: the imported catalogues' and the default one's. */
	public List<PaletteType> palette() {
		if (paletteOf != current) {
			palette = List.copyOf(Palette.of(model(), injector.getInstance(IScopeProvider.class)));
			paletteOf = current;
		}
		return palette;
	}

	/**
	 * Takes a text that changed outside the editor (the file was saved by a text editor): the diagram follows it,
	 * and the undo history, which is made of edits of the previous text, is forgotten.
	 */
	public EditResult reset(String text) {
		List<TextEdit> edits = TextEdits.between(current.text(), text);
		Version next = parse(text);
		if (next.testCase() == null) {
			throw new IllegalArgumentException("the new text is not a test case ('testcase NAME { room ... }')");
		}
		current = next;
		undo.clear();
		redo.clear();
		return result(edits);
	}

	/** Writes the current text back to the file it came from. */
	public void save() throws IOException {
		if (!uri.isFile()) {
			throw new IOException("not a file: " + uri);
		}
		Files.writeString(Path.of(uri.toFileString()), text(), StandardCharsets.UTF_8);
	}

	public EditResult apply(EditOperation... operations) {
		return apply(List.of(operations));
	}

	/**
	 * Applies the operations as one change (one undo step). A batch the serializer cannot write in one go (two new
	 * statements at one place of a list, an element added and then changed) is applied one operation after the
	 * other; its edit is then the one replacement that spans all changes.
	 *
	 * @throws EditRefusedException when one cannot be expressed; the document is unchanged
	 * @throws IllegalStateException when the written text would not read back as the edited model; unchanged too
	 */
	public EditResult apply(List<EditOperation> operations) {
		String before = current.text();
		serializeNanos = parseNanos = validateNanos = compareNanos = 0;
		try {
			Written written;
			try {
				written = write(current, operations);
			} catch (TangledListException | ReadBackException | ModelEditor.ChangesNewElementException e) {
				if (operations.size() < 2) {
					throw e;
				}
				Version step = parse(before);
				for (EditOperation operation : operations) {
					step = write(step, List.of(operation)).next();
				}
				written = new Written(TextEdits.between(before, step.text()), step);
			}
			undo.push(new Step(written.edits(), TextEdits.inverse(before, written.edits())));
			redo.clear();
			current = written.next();
			return result(written.edits());
		} catch (RuntimeException | Error e) {
			current = parse(before); // the model may be half edited: read the text again
			throw e;
		}
	}

	private record Written(List<TextEdit> edits, Version next) {
	}

	/** The written text read back as something else than the edited model. */
	private static final class ReadBackException extends IllegalStateException {
		private static final long serialVersionUID = 1L;

		ReadBackException(String message) {
			super(message);
		}
	}

	/** Edits the version's model (which is spent afterwards) and returns the text edits and the re-read result. */
	private Written write(Version version, List<EditOperation> operations) {
		TestCase testCase = version.testCase();
		IChangeSerializer serializer = injector.getInstance(IChangeSerializer.class);
		// one file is edited and nothing is renamed: no other file or reference needs updating
		serializer.setUpdateRelatedFiles(false);
		serializer.setUpdateCrossReferences(false);
		PeopleRefusals.check(testCase, operations);
		ModelEditor editor = new ModelEditor(testCase, injector.getInstance(IScopeProvider.class), reservedWords);
		serializer.addModification(version.resource(), resource -> operations.forEach(editor::apply));
		List<IEmfResourceChange> changes = new ArrayList<>();
		long start = System.nanoTime();
		serializer.applyModifications(changes::add);
		List<TextEdit> edits = TextEdits.tidy(version.text(), TextEdits.sorted(replacements(changes)));
		serializeNanos += System.nanoTime() - start;
		Version next = parse(TextEdits.apply(version.text(), edits));
		start = System.nanoTime();
		boolean equal = SameModel.equal(testCase, next.testCase());
		compareNanos += System.nanoTime() - start;
		if (!equal) {
			throw new ReadBackException("The written text does not read back as the edited room; nothing was "
					+ "changed.\nWritten text:\n" + next.text() + "\nits errors: " + next.resource().getErrors());
		}
		return new Written(edits, next);
	}

	public boolean canUndo() {
		return !undo.isEmpty();
	}

	public boolean canRedo() {
		return !redo.isEmpty();
	}

	/** Reverts the last change by the inverse of its text edits. */
	public EditResult undo() {
		if (undo.isEmpty()) {
			throw new IllegalStateException("nothing to undo");
		}
		Step step = undo.peek();
		current = parse(TextEdits.apply(current.text(), step.backward()));
		redo.push(undo.pop());
		return result(step.backward());
	}

	public EditResult redo() {
		if (redo.isEmpty()) {
			throw new IllegalStateException("nothing to redo");
		}
		Step step = redo.peek();
		current = parse(TextEdits.apply(current.text(), step.forward()));
		undo.push(redo.pop());
		return result(step.forward());
	}

	private EditResult result(List<TextEdit> edits) {
		return new EditResult(current.text(), List.copyOf(edits), current.issues());
	}

	/** A fresh resource set per version: the edited model and its re-read text can be compared side by side. */
	private Version parse(String text) {
		XtextResourceSet resourceSet = injector.getInstance(XtextResourceSet.class);
		IResourceFactory factory = injector.getInstance(IResourceFactory.class);
		resourceSet.getResourceFactoryRegistry().getExtensionToFactoryMap().put("rei", factory);
		if (uri.fileExtension() != null) {
			resourceSet.getResourceFactoryRegistry().getExtensionToFactoryMap().put(uri.fileExtension(), factory);
		}
		long start = System.nanoTime();
		XtextResource resource = (XtextResource) resourceSet.createResource(uri);
		try {
			resource.load(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)),
					Map.of(XtextResource.OPTION_ENCODING, StandardCharsets.UTF_8.name()));
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
		EcoreUtil.resolveAll(resource);
		long parsed = System.nanoTime();
		parseNanos += parsed - start;
		List<ValidationIssue> issues = Issues.of(resource);
		validateNanos += System.nanoTime() - parsed;
		return new Version(text, resource, issues);
	}

	Timings lastTimings() {
		return new Timings(serializeNanos / 1_000_000, parseNanos / 1_000_000, validateNanos / 1_000_000,
				compareNanos / 1_000_000);
	}

	private static List<TextEdit> replacements(List<IEmfResourceChange> changes) {
		List<TextEdit> edits = new ArrayList<>();
		for (IEmfResourceChange change : changes) {
			if (change instanceof ITextDocumentChange text) {
				for (ITextReplacement replacement : text.getReplacements()) {
					edits.add(new TextEdit(replacement.getOffset(), replacement.getLength(),
							replacement.getReplacementText()));
				}
			}
		}
		return edits;
	}

	/** Keywords cannot be names, except those the grammar's ValidID lets through ({@code x}, {@code s}, ...). */
	private static Set<String> reservedWords(IGrammarAccess grammar) {
		Set<String> words = new HashSet<>(GrammarUtil.getAllKeywords(grammar.getGrammar()));
		var validId = GrammarUtil.findRuleForName(grammar.getGrammar(), "ValidID");
		if (validId != null) {
			EcoreUtil2.getAllContentsOfType(validId, Keyword.class).forEach(k -> words.remove(k.getValue()));
		}
		return words;
	}
}

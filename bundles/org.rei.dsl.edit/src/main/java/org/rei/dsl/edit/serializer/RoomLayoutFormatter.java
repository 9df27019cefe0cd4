/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.serializer;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.formatting2.AbstractJavaFormatter;
import org.eclipse.xtext.formatting2.FormatterPreferenceKeys;
import org.eclipse.xtext.formatting2.FormatterRequest;
import org.eclipse.xtext.formatting2.IFormattableDocument;
import org.eclipse.xtext.formatting2.IHiddenRegionFormatter;
import org.eclipse.xtext.formatting2.regionaccess.ISemanticRegion;
import org.eclipse.xtext.formatting2.regionaccess.ITextRegionAccess;
import org.eclipse.xtext.formatting2.regionaccess.ITextRegionAccessDiff;
import org.eclipse.xtext.preferences.TypedPreferenceKey;
import org.rei.context.BuildingBlock;
import org.rei.context.Environment;
import org.rei.context.Mission;
import org.rei.context.MonitorSpec;
import org.rei.context.PhysicalObject;
import org.rei.context.Task;
import org.rei.context.TestCase;

/**
 * Lays out what the change serializer writes: one statement per line in a block written over several lines (one
 * space apart in a block written on one line), indented like the file's own statements, tokens one space apart
 * except around brackets and commas. Only the regions an edit touched are formatted (RegionDiffFormatter drops the
 * rest), so the user's layout elsewhere stays as it is.
 */
public class RoomLayoutFormatter extends AbstractJavaFormatter {

	/** A statement of the test case's block at the start of a line: its leading blanks are one indentation. */
	private static final Pattern LEVEL_ONE = Pattern.compile("^([ \\t]+)(room|mission|monitor)\\b", Pattern.MULTILINE);
	static final String DEFAULT_INDENTATION = "  ";

	private String indentation = DEFAULT_INDENTATION;
	private String lineSeparator = "\n";

	@Override
	protected void initialize(FormatterRequest request) {
		super.initialize(request);
		ITextRegionAccess access = request.getTextRegionAccess();
		if (access instanceof ITextRegionAccessDiff diff) {
			access = diff.getOriginalTextRegionAccess();
		}
		String text = access.regionForDocument().getText();
		Matcher level = LEVEL_ONE.matcher(text);
		indentation = level.find() ? level.group(1) : DEFAULT_INDENTATION;
		lineSeparator = text.contains("\r\n") ? "\r\n" : "\n";
	}

	/** The file's own indentation and line ends, whatever the preferences say. */
	@SuppressWarnings("unchecked")
	@Override
	public <T> T getPreference(TypedPreferenceKey<T> key) {
		if (key == FormatterPreferenceKeys.indentation) {
			return (T) indentation;
		}
		if (key == FormatterPreferenceKeys.lineSeparator) {
			return (T) lineSeparator;
		}
		return super.getPreference(key);
	}

	protected void format(TestCase testCase, IFormattableDocument doc) {
		List<EObject> statements = new ArrayList<>();
		addIfWritten(statements, testCase.getOwnedEnvironment());
		addIfWritten(statements, testCase.getOwnedMission());
		addIfWritten(statements, testCase.getOwnedMonitor());
		block(testCase, statements, List.of(), doc);
		statements.forEach(doc::format);
	}

	protected void format(Environment environment, IFormattableDocument doc) {
		List<EObject> statements = new ArrayList<>();
		environment.getOwnedBlocks().forEach(block -> addIfWritten(statements, block));
		environment.getOwnedObjects().forEach(object -> addIfWritten(statements, object));
		addIfWritten(statements, environment.getOwnedRobot());
		// a room may have ten thousand floors: only the statements an edit touched are laid out
		statements.removeIf(statement -> !isInRequestedRange(statement));
		block(environment, statements, List.of(), doc);
		inline(environment, doc);
		statements.forEach(doc::format);
	}

	protected void format(Mission mission, IFormattableDocument doc) {
		List<EObject> statements = new ArrayList<>();
		mission.getOwnedTasks().forEach(task -> addIfWritten(statements, task));
		block(mission, statements, regionFor(mission).keywords("tolerance", "timeout"), doc);
		inline(mission, doc);
		statements.forEach(doc::format);
	}

	protected void format(MonitorSpec monitor, IFormattableDocument doc) {
		block(monitor, List.of(), regionFor(monitor).keywords("close", "collision", "maxHumanCollisions"), doc);
		inline(monitor, doc);
	}

	protected void format(BuildingBlock block, IFormattableDocument doc) {
		statement(block, doc);
	}

	protected void format(PhysicalObject object, IFormattableDocument doc) {
		statement(object, doc);
	}

	protected void format(Task task, IFormattableDocument doc) {
		statement(task, doc);
	}

	/** A one-line statement (an object, a floor, a goal): its tokens and those of its parts. */
	private void statement(EObject statement, IFormattableDocument doc) {
		for (ISemanticRegion region : allSemanticRegions(statement)) {
			doc.append(region, this::spaceAfter);
		}
		closeUp(statement, doc);
	}

	/** Tokens of a block statement itself, up to its '{'. */
	private void inline(EObject owner, IFormattableDocument doc) {
		ISemanticRegion open = regionFor(owner).keyword("{");
		for (ISemanticRegion region : semanticRegions(owner)) {
			if (region == open) {
				break;
			}
			doc.append(region, this::spaceAfter);
		}
	}

	/** Statements on their own lines, one indentation deeper than the braces; or one space apart. */
	private void block(EObject owner, List<EObject> statements, List<ISemanticRegion> keywordStatements,
			IFormattableDocument doc) {
		ISemanticRegion open = regionFor(owner).keyword("{");
		ISemanticRegion close = regionFor(owner).keyword("}");
		if (open == null || close == null) {
			return;
		}
		boolean multiline = open.getNextHiddenRegion().isMultiline() || close.getPreviousHiddenRegion().isMultiline();
		if (multiline) {
			doc.interior(open, close, this::indent);
		}
		for (EObject statement : statements) {
			doc.prepend(statement, multiline ? this::statementBreak : this::oneSpace);
		}
		for (ISemanticRegion keyword : keywordStatements) {
			doc.prepend(keyword, multiline ? this::statementBreak : this::oneSpace);
		}
		doc.prepend(close, multiline ? this::statementBreak : this::oneSpace);
	}

	private void closeUp(EObject statement, IFormattableDocument doc) {
		for (ISemanticRegion comma : allRegionsFor(statement).keywords(",")) {
			doc.prepend(comma, this::noSpace);
		}
		for (ISemanticRegion open : allRegionsFor(statement).keywords("[")) {
			doc.append(open, this::noSpace);
		}
		for (ISemanticRegion close : allRegionsFor(statement).keywords("]")) {
			doc.prepend(close, this::noSpace);
		}
	}

	private void statementBreak(IHiddenRegionFormatter it) {
		it.setNewLines(1);
	}

	/** The default between two tokens; anything more specific wins. */
	private void spaceAfter(IHiddenRegionFormatter it) {
		it.oneSpace();
		it.lowPriority();
	}

	private void addIfWritten(List<EObject> statements, EObject statement) {
		if (statement != null && regionForEObject(statement) != null) {
			statements.add(statement);
		}
	}
}

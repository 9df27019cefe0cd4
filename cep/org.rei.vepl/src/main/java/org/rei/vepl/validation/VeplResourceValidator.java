/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.vepl.validation;

import java.util.ArrayList;
import java.util.List;

import org.apache.log4j.Logger;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.service.OperationCanceledManager;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.CheckType;
import org.eclipse.xtext.validation.Issue;
import org.eclipse.xtext.validation.ResourceValidatorImpl;
import org.rei.vepl.vepl.PatternFile;

import com.google.inject.Inject;

/**
 * Every check of a .vepl file, for the loader ({@code rei run --patterns}, the monitor) and the language server
 * alike: the syntax errors (among them the parser's refusal of brackets nested too deep), the checks of
 * {@link VeplValidator}, and those that need the whole resource: a file that declares nothing, whether or not the
 * parser made a model of it. A check that fails (a bug) is logged and reported as an error of the file, so it stops
 * neither the server's build nor the loader's report of the other files.
 */
public class VeplResourceValidator extends ResourceValidatorImpl {

	private static final Logger LOG = Logger.getLogger(VeplResourceValidator.class);

	@Inject
	private OperationCanceledManager cancellation;

	@Override
	public List<Issue> validate(Resource resource, CheckMode mode, CancelIndicator indicator) {
		try {
			List<Issue> issues = new ArrayList<>(super.validate(resource, mode, indicator));
			if (mode.shouldCheck(CheckType.FAST) && declaresNothing(resource)
					&& issues.stream().noneMatch(i -> i.getSeverity() == Severity.ERROR && i.isSyntaxError())) {
				issues.add(atStart("The file declares no event, signal or rule (queryEvent, atomicEvent, complexEvent, "
						+ "signal, rule)", VeplIssueCodes.EMPTY_FILE));
			}
			return issues;
		} catch (RuntimeException | StackOverflowError e) {
			cancellation.propagateIfCancelException(e);
			LOG.error("checking " + resource.getURI() + " failed; the file gets an error instead", e);
			return List.of(atStart("The file could not be checked (" + e + "): please report it with the file",
					VeplIssueCodes.UNREADABLE));
		}
	}

	/** No model (nothing but whitespace and comments) or one without elements (a header only). */
	private static boolean declaresNothing(Resource resource) {
		return resource.getContents().isEmpty()
				|| resource.getContents().get(0) instanceof PatternFile f && f.getElements().isEmpty();
	}

	/** An error on the file's first character: line 1, column 1. */
	private static Issue atStart(String message, String code) {
		Issue.IssueImpl issue = new Issue.IssueImpl();
		issue.setSeverity(Severity.ERROR);
		issue.setType(CheckType.FAST);
		issue.setMessage(message);
		issue.setCode(code);
		issue.setLineNumber(1);
		issue.setColumn(1);
		issue.setLineNumberEnd(1);
		issue.setColumnEnd(1);
		issue.setOffset(0);
		issue.setLength(0);
		return issue;
	}
}

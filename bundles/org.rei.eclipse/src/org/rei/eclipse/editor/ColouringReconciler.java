// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.editor;

import java.util.Set;

import org.eclipse.jface.text.DocumentEvent;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.IRegion;
import org.eclipse.jface.text.ITypedRegion;
import org.eclipse.jface.text.Region;
import org.eclipse.jface.text.TextAttribute;
import org.eclipse.jface.text.presentation.IPresentationDamager;
import org.eclipse.jface.text.presentation.PresentationReconciler;
import org.eclipse.jface.text.rules.DefaultDamagerRepairer;
import org.eclipse.jface.text.rules.EndOfLineRule;
import org.eclipse.jface.text.rules.IRule;
import org.eclipse.jface.text.rules.IToken;
import org.eclipse.jface.text.rules.IWordDetector;
import org.eclipse.jface.text.rules.MultiLineRule;
import org.eclipse.jface.text.rules.NumberRule;
import org.eclipse.jface.text.rules.RuleBasedScanner;
import org.eclipse.jface.text.rules.SingleLineRule;
import org.eclipse.jface.text.rules.Token;
import org.eclipse.jface.text.rules.WordRule;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.RGB;
import org.eclipse.jface.resource.JFaceResources;

/**
 * Syntax colouring of .rei and .vepl: the grammar's keywords, comments, strings and numbers (Xtext's common
 * terminals, which both grammars use). The whole text is re-coloured on each change, so a comment opened on one
 * line colours the lines after it; REI's files are small enough for that to cost nothing noticeable.
 */
public abstract class ColouringReconciler extends PresentationReconciler {
	private static final RGB KEYWORD = new RGB(127, 0, 85);
	private static final RGB COMMENT = new RGB(63, 127, 95);
	private static final RGB STRING = new RGB(42, 0, 255);
	private static final RGB NUMBER = new RGB(125, 125, 125);

	protected ColouringReconciler(String grammar) {
		DefaultDamagerRepairer repairer = new DefaultDamagerRepairer(scanner(Keywords.of(grammar)));
		setDamager(new WholeDocument(), IDocument.DEFAULT_CONTENT_TYPE);
		setRepairer(repairer, IDocument.DEFAULT_CONTENT_TYPE);
	}

	/** .rei test cases. */
	public static final class Rei extends ColouringReconciler {
		public Rei() {
			super("Rei.xtext");
		}
	}

	/** .vepl temporal patterns. */
	public static final class Vepl extends ColouringReconciler {
		public Vepl() {
			super("Vepl.xtext");
		}
	}

	private static RuleBasedScanner scanner(Set<String> keywords) {
		IToken keyword = token(KEYWORD, SWT.BOLD);
		IToken comment = token(COMMENT, SWT.NORMAL);
		IToken string = token(STRING, SWT.NORMAL);
		// Every identifier is one token (keyword or plain), so the digits in "table1" are not a number.
		WordRule words = new WordRule(new Identifier(), new Token(null));
		keywords.forEach(word -> words.addWord(word, keyword));
		RuleBasedScanner scanner = new RuleBasedScanner();
		scanner.setRules(new IRule[] { new EndOfLineRule("//", comment), new MultiLineRule("/*", "*/", comment, (char) 0, true),
				new SingleLineRule("\"", "\"", string, '\\'), new SingleLineRule("'", "'", string, '\\'), words,
				new NumberRule(token(NUMBER, SWT.NORMAL)) });
		return scanner;
	}

	private static IToken token(RGB colour, int style) {
		String key = "org.rei.eclipse.colour." + colour;
		if (!JFaceResources.getColorRegistry().hasValueFor(key)) {
			JFaceResources.getColorRegistry().put(key, colour);
		}
		return new Token(new TextAttribute(JFaceResources.getColorRegistry().get(key), null, style));
	}

	private static final class Identifier implements IWordDetector {
		@Override
		public boolean isWordStart(char c) {
			return Character.isLetter(c) || c == '_';
		}

		@Override
		public boolean isWordPart(char c) {
			return Character.isLetterOrDigit(c) || c == '_';
		}
	}

	/** Damages the whole document: see the class comment. */
	private static final class WholeDocument implements IPresentationDamager {
		private IDocument document;

		@Override
		public void setDocument(IDocument newDocument) {
			document = newDocument;
		}

		@Override
		public IRegion getDamageRegion(ITypedRegion partition, DocumentEvent event, boolean documentPartitioningChanged) {
			return new Region(0, document.getLength());
		}
	}
}

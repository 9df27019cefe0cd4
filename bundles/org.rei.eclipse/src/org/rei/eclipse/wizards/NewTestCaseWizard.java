// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.wizards;

import java.io.ByteArrayInputStream;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;

import org.eclipse.core.resources.IFile;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.ui.INewWizard;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.dialogs.WizardNewFileCreationPage;
import org.eclipse.ui.ide.IDE;
import org.eclipse.jface.wizard.Wizard;
import org.rei.eclipse.ReiPlugin;

/** File > New > Other > REI > Test case: a small valid test case to start from, opened in its editor. */
public final class NewTestCaseWizard extends Wizard implements INewWizard {
	private IWorkbench workbench;
	private IStructuredSelection selection;
	private WizardNewFileCreationPage page;

	@Override
	public void init(IWorkbench newWorkbench, IStructuredSelection newSelection) {
		workbench = newWorkbench;
		selection = newSelection;
		setWindowTitle("New REI Test Case");
	}

	@Override
	public void addPages() {
		page = new WizardNewFileCreationPage("testCase", selection) {
			@Override
			protected InputStream getInitialContents() {
				return new ByteArrayInputStream(contents(getFileName()).getBytes(StandardCharsets.UTF_8));
			}
		};
		page.setTitle("REI test case");
		page.setDescription("A room with a table, a robot and a mission of two goals, to edit from there.");
		page.setFileExtension("rei");
		page.setFileName("new_test_case.rei");
		addPage(page);
	}

	@Override
	public boolean performFinish() {
		IFile file = page.createNewFile();
		if (file == null) {
			return false;
		}
		try {
			IDE.openEditor(workbench.getActiveWorkbenchWindow().getActivePage(), file);
		} catch (PartInitException failed) {
			ReiPlugin.log("cannot open " + file.getFullPath(), failed);
		}
		return true;
	}

	/** The new file's text: a valid test case named after the file. */
	public static String contents(String fileName) {
		String name = testCaseName(fileName.replaceFirst("\\.rei$", ""));
		return """
				// %s: a 4 x 3 m room with a table, a TurtleBot3 Waffle and a mission of two goals.
				// Floors are named F_<column>_<row>; hover a name to see where it is, Ctrl+Space to complete.
				testcase %s {
				  room Room size 4 x 3 {
				    object table1 : Table on F_2_1
				    robot robot1 : Waffle on F_0_0
				  }
				  mission AcrossTheRoom {
				    goto F_3_0
				    goto F_3_2 within 60s
				  }
				  monitor { close 0.25 collision 0.01 }
				}
				""".formatted(name, name);
	}

	/** An identifier from a file name: letters, digits and underscores, in CamelCase, starting with a letter. */
	static String testCaseName(String base) {
		StringBuilder name = new StringBuilder();
		boolean upper = true;
		for (char c : base.toCharArray()) {
			if (Character.isLetterOrDigit(c)) {
				name.append(upper ? Character.toUpperCase(c) : c);
				upper = false;
			} else {
				upper = true;
			}
		}
		if (name.isEmpty() || !Character.isLetter(name.charAt(0))) {
			name.insert(0, "TestCase");
		}
		return name.toString();
	}
}

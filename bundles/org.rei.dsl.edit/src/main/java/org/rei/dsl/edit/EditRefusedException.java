/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit;

/**
 * An edit the text cannot express (an unknown name, a floor of a grid room, a floor something stands on): the
 * document is left as it was. Everything the text can express is applied, and the validators judge it.
 */
public class EditRefusedException extends RuntimeException {

	private static final long serialVersionUID = 1L;

	public EditRefusedException(String message) {
		super(message);
	}
}

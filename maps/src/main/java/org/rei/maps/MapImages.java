/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.maps;

import java.awt.image.Raster;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Iterator;

import javax.imageio.IIOException;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.stream.ImageInputStream;

import org.w3c.dom.Node;

/**
 * A map's image as Nav2's {@code map_io} sees it: per pixel the mean of red, green and blue (a grey pixel's grey)
 * and the alpha, both as fractions of the sample's full scale (255, 65535, a PGM's maxval, or 2^depth - 1), in
 * image row order (row 0 at the top). PGM ({@code P2}, {@code P5}, maxval up to 65535) is read here, PNG by
 * javax.imageio with the samples as stored (no gamma), the palette and a {@code tRNS} transparent colour resolved
 * as the Python side (pypng) and ImageMagick read them.
 */
final class MapImages {

	private static final byte[] PNG_SIGNATURE = { (byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };

	/** The pixels of an image; {@code alpha} is null without an alpha channel. */
	record Pixels(int width, int height, double[] shade, double[] alpha) {
	}

	/** Where an image problem is reported: the YAML's {@code image} field. */
	interface Problems {
		MapException at(String detail);
	}

	private MapImages() {
	}

	/** {@code pgm} or {@code png} by the file's first bytes; {@code pgm} when unreadable (never asked then). */
	static String formatOf(Path image) {
		try (InputStream in = Files.newInputStream(image)) {
			return Arrays.equals(in.readNBytes(8), PNG_SIGNATURE) ? "png" : "pgm";
		} catch (IOException e) {
			return "pgm";
		}
	}

	static Pixels read(Path image, Problems problems) throws MapException {
		byte[] head;
		try (InputStream in = Files.newInputStream(image)) {
			head = in.readNBytes(8);
		} catch (IOException e) {
			throw problems.at("cannot read the image " + image + ": " + reason(e));
		}
		if (head.length >= 2 && head[0] == 'P' && (head[1] == '2' || head[1] == '5')) {
			return readPgm(image, problems);
		}
		if (Arrays.equals(head, PNG_SIGNATURE)) {
			return readPng(image, problems);
		}
		throw problems.at("cannot read the image " + image + ": not a PGM (P2, P5) or PNG file");
	}

	private static String reason(IOException e) {
		if (e instanceof java.nio.file.NoSuchFileException) {
			return "No such file or directory";
		}
		if (e instanceof java.nio.file.AccessDeniedException) {
			return "Permission denied";
		}
		return e.getMessage() != null ? e.getMessage() : e.toString();
	}

	private static boolean space(byte b) {
		return b == ' ' || b == '\t' || b == '\n' || b == '\r' || b == 0x0b || b == 0x0c;
	}

	/** A PGM: three header numbers and the samples, whose shade is {@code sample / maxval} as map_server reads it. */
	private static Pixels readPgm(Path image, Problems problems) throws MapException {
		byte[] data;
		try {
			data = Files.readAllBytes(image);
		} catch (IOException e) {
			throw problems.at("cannot read the image " + image + ": " + reason(e));
		}
		String[] tokens = new String[3];
		int found = 0;
		int at = 2;
		while (found < 3) {
			while (at < data.length && space(data[at])) {
				at++;
			}
			if (at < data.length && data[at] == '#') {
				while (at < data.length && data[at] != '\n' && data[at] != '\r') {
					at++;
				}
				continue;
			}
			int start = at;
			while (at < data.length && !space(data[at]) && data[at] != '#') {
				at++;
			}
			if (start == at) {
				throw problems.at(image + ": truncated PGM header");
			}
			tokens[found++] = new String(data, start, at - start, java.nio.charset.StandardCharsets.ISO_8859_1);
		}
		long width;
		long height;
		long maxval;
		try {
			width = Long.parseLong(tokens[0]);
			height = Long.parseLong(tokens[1]);
			maxval = Long.parseLong(tokens[2]);
		} catch (NumberFormatException e) {
			throw problems.at(image + ": PGM header '" + String.join(" ", tokens) + "' is not three integers");
		}
		if (width <= 0 || height <= 0) {
			throw problems.at(image + ": PGM size " + width + " x " + height + ": expected at least 1 x 1");
		}
		if (!(0 < maxval && maxval <= 65535)) {
			throw problems.at(image + ": PGM maxval " + maxval + ": expected 1..65535 (8 or 16 bits per sample)");
		}
		long count = width * height;
		if (count > Integer.MAX_VALUE / 2) {
			throw problems.at(image + ": PGM size " + width + " x " + height + ": too many cells");
		}
		int n = (int) count;
		double[] shade = new double[n];
		int largest = 0;
		if (data[1] == '5') {
			int size = maxval > 255 ? 2 : 1;
			int body = at + 1; // exactly one whitespace byte ends the header
			long available = Math.max(0, data.length - body) / size;
			if (available < count) {
				throw problems.at(image + ": PGM data holds " + available + " samples, expected " + width + " x "
						+ height + " = " + count);
			}
			for (int i = 0; i < n; i++) {
				int sample = size == 2 ? ((data[body + 2 * i] & 0xff) << 8) | (data[body + 2 * i + 1] & 0xff)
						: data[body + i] & 0xff;
				largest = Math.max(largest, sample);
				shade[i] = (double) sample / maxval;
			}
		} else {
			int i = 0;
			while (i < n) {
				while (at < data.length && space(data[at])) {
					at++;
				}
				if (at >= data.length) {
					throw problems.at(image + ": PGM data holds " + i + " samples, expected " + width + " x " + height
							+ " = " + count);
				}
				long sample = 0;
				boolean digits = true;
				int start = at;
				while (at < data.length && !space(data[at])) {
					byte b = data[at++];
					digits &= b >= '0' && b <= '9';
					if (digits) {
						sample = Math.min(sample * 10 + (b - '0'), Integer.MAX_VALUE);
					}
				}
				if (!digits) {
					// Python's int() also takes a sign; only a stray word fails there as here
					String word = new String(data, start, at - start, java.nio.charset.StandardCharsets.ISO_8859_1);
					try {
						sample = Long.parseLong(word.startsWith("+") ? word.substring(1) : word);
					} catch (NumberFormatException e) {
						throw problems.at(image + ": PGM samples are not integers");
					}
				}
				largest = (int) Math.max(largest, Math.min(sample, Integer.MAX_VALUE));
				shade[i++] = (double) sample / maxval;
			}
		}
		if (largest > maxval) {
			throw problems.at(image + ": a PGM sample of " + largest + " exceeds maxval " + maxval);
		}
		return new Pixels((int) width, (int) height, shade, null);
	}

	private static Pixels readPng(Path image, Problems problems) throws MapException {
		try (ImageInputStream in = ImageIO.createImageInputStream(image.toFile())) {
			Iterator<ImageReader> readers = ImageIO.getImageReaders(in);
			if (!readers.hasNext()) {
				throw problems.at("cannot read the image " + image + ": no PNG reader");
			}
			ImageReader reader = readers.next();
			try {
				reader.setInput(in, true, false);
				IIOMetadata metadata = reader.getImageMetadata(0);
				Raster raster = reader.read(0).getRaster();
				return pngPixels(raster, (Node) metadata.getAsTree("javax_imageio_png_1.0"));
			} finally {
				reader.dispose();
			}
		} catch (IIOException e) {
			throw problems.at("cannot read the image " + image + ": " + e.getMessage()
					+ (e.getCause() != null ? ": " + e.getCause().getMessage() : ""));
		} catch (IOException | RuntimeException e) {
			throw problems.at("cannot read the image " + image + ": " + e);
		}
	}

	/**
	 * The samples of a PNG as stored: IHDR says the colour type and depth, PLTE and tRNS the palette and the
	 * transparent colour (pypng's {@code read}, which the Python side uses, resolves them the same way).
	 */
	private static Pixels pngPixels(Raster raster, Node tree) {
		Node ihdr = child(tree, "IHDR");
		String colourType = attribute(ihdr, "colorType");
		int depth = Integer.parseInt(attribute(ihdr, "bitDepth"));
		int w = raster.getWidth();
		int h = raster.getHeight();
		int n = w * h;
		double[] shade = new double[n];
		double[] alpha = null;
		Node trns = child(tree, "tRNS");
		if ("Palette".equals(colourType)) {
			Node plte = child(tree, "PLTE");
			int[][] palette = new int[256][4];
			for (int[] entry : palette) {
				entry[3] = 255;
			}
			for (Node e = plte.getFirstChild(); e != null; e = e.getNextSibling()) {
				int i = Integer.parseInt(attribute(e, "index"));
				palette[i][0] = Integer.parseInt(attribute(e, "red"));
				palette[i][1] = Integer.parseInt(attribute(e, "green"));
				palette[i][2] = Integer.parseInt(attribute(e, "blue"));
			}
			Node alphas = trns == null ? null : child(trns, "tRNS_Palette");
			if (alphas != null) {
				for (Node e = alphas.getFirstChild(); e != null; e = e.getNextSibling()) {
					palette[Integer.parseInt(attribute(e, "index"))][3] = Integer.parseInt(attribute(e, "alpha"));
				}
				alpha = new double[n];
			}
			int[] index = raster.getSamples(0, 0, w, h, 0, new int[n]);
			for (int i = 0; i < n; i++) {
				int[] c = palette[index[i]];
				shade[i] = (c[0] + c[1] + c[2]) / 3.0 / 255.0;
				if (alpha != null) {
					alpha[i] = c[3] / 255.0;
				}
			}
			return new Pixels(w, h, shade, alpha);
		}
		double full = Math.pow(2, depth) - 1;
		boolean grey = colourType.startsWith("Gray");
		int colours = grey ? 1 : 3;
		int[][] bands = new int[colours][];
		for (int b = 0; b < colours; b++) {
			bands[b] = raster.getSamples(0, 0, w, h, b, new int[n]);
		}
		for (int i = 0; i < n; i++) {
			shade[i] = grey ? bands[0][i] / full : (bands[0][i] + bands[1][i] + bands[2][i]) / 3.0 / full;
		}
		if (colourType.endsWith("Alpha")) {
			int[] a = raster.getSamples(0, 0, w, h, colours, new int[n]);
			alpha = new double[n];
			for (int i = 0; i < n; i++) {
				alpha[i] = a[i] / full;
			}
		} else if (trns != null) {
			// one colour (or grey) stands for transparent: alpha 0 there, opaque elsewhere
			Node key = child(trns, grey ? "tRNS_Grayscale" : "tRNS_RGB");
			if (key != null) {
				int[] k = grey ? new int[] { Integer.parseInt(attribute(key, "gray")) }
						: new int[] { Integer.parseInt(attribute(key, "red")),
								Integer.parseInt(attribute(key, "green")), Integer.parseInt(attribute(key, "blue")) };
				alpha = new double[n];
				for (int i = 0; i < n; i++) {
					boolean match = true;
					for (int b = 0; b < colours; b++) {
						match &= bands[b][i] == k[b];
					}
					alpha[i] = match ? 0.0 : 1.0;
				}
			}
		}
		return new Pixels(w, h, shade, alpha);
	}

	private static Node child(Node parent, String name) {
		for (Node c = parent.getFirstChild(); c != null; c = c.getNextSibling()) {
			if (name.equals(c.getNodeName())) {
				return c;
			}
		}
		return null;
	}

	private static String attribute(Node node, String name) {
		return node.getAttributes().getNamedItem(name).getNodeValue();
	}
}

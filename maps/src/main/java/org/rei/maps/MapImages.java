/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.maps;

import java.awt.image.Raster;
import java.io.IOException;
import java.io.InputStream;
import java.math.BigInteger;
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
 * <p>
 * The image's size is checked from its header (PNG IHDR, PGM header) before anything is decoded: at most
 * {@link OccupancyMap#MAX_CELLS} cells. The pixels go to a {@link Rows} one row at a time, so that reading holds
 * no more than the cells themselves (and, for a PNG, its decoded raster).
 */
final class MapImages {

	private static final byte[] PNG_SIGNATURE = { (byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };

	/** Where an image problem is reported: the YAML's {@code image} field. */
	interface Problems {
		MapException at(String detail);
	}

	/** Where the pixels go: the size first, then every row from the top, each in arrays reused for the next. */
	interface Rows {
		void start(int width, int height);

		/** {@code alpha} is null for an image without an alpha channel or transparent colour. */
		void row(int row, double[] shade, double[] alpha);
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

	static void read(Path image, Problems problems, Rows rows) throws MapException {
		byte[] head;
		try (InputStream in = Files.newInputStream(image)) {
			head = in.readNBytes(24); // the signature, then the first chunk's length, type and IHDR's size
		} catch (IOException e) {
			throw problems.at("cannot read the image " + image + ": " + reason(e));
		}
		if (head.length >= 2 && head[0] == 'P' && (head[1] == '2' || head[1] == '5')) {
			readPgm(image, problems, rows);
			return;
		}
		if (head.length >= 8 && Arrays.equals(Arrays.copyOf(head, 8), PNG_SIGNATURE)) {
			if (head.length == 24 && head[12] == 'I' && head[13] == 'H' && head[14] == 'D' && head[15] == 'R') {
				checkSize(image, problems, BigInteger.valueOf(unsigned(head, 16)),
						BigInteger.valueOf(unsigned(head, 20)));
			} // else not a PNG the decoder can read: it says why
			readPng(image, problems, rows);
			return;
		}
		throw problems.at("cannot read the image " + image + ": not a PGM (P2, P5) or PNG file");
	}

	/** The cell limit, before anything is decoded; the same message as the Python side's. */
	private static void checkSize(Path image, Problems problems, BigInteger width, BigInteger height)
			throws MapException {
		BigInteger cells = width.multiply(height);
		if (cells.compareTo(BigInteger.valueOf(OccupancyMap.MAX_CELLS)) > 0) {
			throw problems.at(image + ": " + width + " x " + height + " = " + cells + " cells: a map may have at most "
					+ OccupancyMap.MAX_CELLS + " cells (crop it, or save it at a coarser resolution)");
		}
	}

	private static long unsigned(byte[] b, int at) {
		return ((b[at] & 0xffL) << 24) | ((b[at + 1] & 0xffL) << 16) | ((b[at + 2] & 0xffL) << 8) | (b[at + 3] & 0xffL);
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

	private static boolean space(int b) {
		return b == ' ' || b == '\t' || b == '\n' || b == '\r' || b == 0x0b || b == 0x0c;
	}

	/** A file read through a buffer of its own, byte by byte or in runs, counting where it is. */
	private static final class Bytes implements AutoCloseable {
		private final InputStream in;
		private final byte[] buffer = new byte[1 << 16];
		private int at;
		private int end;
		long offset; // of the next byte in the file

		Bytes(Path file) throws IOException {
			in = Files.newInputStream(file);
		}

		/** The next byte without taking it, -1 at the end. */
		int peek() throws IOException {
			if (at == end) {
				end = Math.max(0, in.read(buffer, 0, buffer.length));
				at = 0;
				if (end == 0) {
					return -1;
				}
			}
			return buffer[at] & 0xff;
		}

		int take() throws IOException {
			int b = peek();
			if (b >= 0) {
				at++;
				offset++;
			}
			return b;
		}

		/** Up to {@code length} bytes into {@code into}; fewer only at the end of the file. */
		int take(byte[] into, int length) throws IOException {
			int n = 0;
			while (n < length && peek() >= 0) {
				int run = Math.min(length - n, end - at);
				System.arraycopy(buffer, at, into, n, run);
				at += run;
				offset += run;
				n += run;
			}
			return n;
		}

		@Override
		public void close() throws IOException {
			in.close();
		}
	}

	/**
	 * A PGM: three header numbers and the samples, whose shade is {@code sample / maxval} as map_server reads it;
	 * read as a stream, the header first.
	 */
	private static void readPgm(Path image, Problems problems, Rows rows) throws MapException {
		try (Bytes data = new Bytes(image)) {
			data.take(); // 'P'
			boolean binary = data.take() == '5';
			String[] tokens = new String[3];
			int found = 0;
			while (found < 3) {
				while (data.peek() >= 0 && space(data.peek())) {
					data.take();
				}
				if (data.peek() == '#') {
					while (data.peek() >= 0 && data.peek() != '\n' && data.peek() != '\r') {
						data.take();
					}
					continue;
				}
				StringBuilder token = new StringBuilder();
				while (data.peek() >= 0 && !space(data.peek()) && data.peek() != '#') {
					token.append((char) data.take());
				}
				if (token.isEmpty()) {
					throw problems.at(image + ": truncated PGM header");
				}
				tokens[found++] = token.toString();
			}
			BigInteger width;
			BigInteger height;
			BigInteger maxval;
			try { // as Python's int(): any number of digits
				width = new BigInteger(tokens[0]);
				height = new BigInteger(tokens[1]);
				maxval = new BigInteger(tokens[2]);
			} catch (NumberFormatException e) {
				throw problems.at(image + ": PGM header '" + String.join(" ", tokens) + "' is not three integers");
			}
			if (width.signum() <= 0 || height.signum() <= 0) {
				throw problems.at(image + ": PGM size " + width + " x " + height + ": expected at least 1 x 1");
			}
			checkSize(image, problems, width, height);
			if (maxval.signum() <= 0 || maxval.compareTo(BigInteger.valueOf(65535)) > 0) {
				throw problems.at(image + ": PGM maxval " + maxval
						+ ": expected 1..65535 (8 or 16 bits per sample)");
			}
			int w = width.intValueExact();
			int h = height.intValueExact();
			int max = maxval.intValueExact();
			rows.start(w, h);
			long largest = binary ? pgmBinary(image, problems, data, w, h, max, rows)
					: pgmPlain(image, problems, data, w, h, max, rows);
			if (largest > max) {
				throw problems.at(image + ": a PGM sample of " + largest + " exceeds maxval " + max);
			}
		} catch (IOException e) {
			throw problems.at("cannot read the image " + image + ": " + reason(e));
		}
	}

	/** P5: exactly one whitespace byte ends the header, then the samples (two bytes, big-endian, above 255). */
	private static long pgmBinary(Path image, Problems problems, Bytes data, int w, int h, int maxval, Rows rows)
			throws IOException, MapException {
		int size = maxval > 255 ? 2 : 1;
		data.take();
		long count = (long) w * h;
		long available = Math.max(0, Files.size(image) - data.offset) / size;
		if (available < count) {
			throw problems.at(image + ": PGM data holds " + available + " samples, expected " + w + " x " + h + " = "
					+ count);
		}
		byte[] bytes = new byte[w * size];
		double[] shade = new double[w];
		int largest = 0;
		for (int row = 0; row < h; row++) {
			data.take(bytes, bytes.length);
			for (int col = 0; col < w; col++) {
				int sample = size == 2 ? ((bytes[2 * col] & 0xff) << 8) | (bytes[2 * col + 1] & 0xff)
						: bytes[col] & 0xff;
				largest = Math.max(largest, sample);
				shade[col] = (double) sample / maxval;
			}
			rows.row(row, shade, null);
		}
		return largest;
	}

	/** P2: the samples as decimal words, as Python's {@code int()} reads them. */
	private static long pgmPlain(Path image, Problems problems, Bytes data, int w, int h, int maxval, Rows rows)
			throws IOException, MapException {
		long count = (long) w * h;
		double[] shade = new double[w];
		long largest = 0;
		long i = 0;
		StringBuilder word = new StringBuilder();
		for (int row = 0; row < h; row++) {
			for (int col = 0; col < w; col++, i++) {
				while (data.peek() >= 0 && space(data.peek())) {
					data.take();
				}
				if (data.peek() < 0) {
					throw problems.at(image + ": PGM data holds " + i + " samples, expected " + w + " x " + h + " = "
							+ count);
				}
				long sample = 0;
				boolean digits = true;
				word.setLength(0);
				while (data.peek() >= 0 && !space(data.peek())) {
					int b = data.take();
					word.append((char) b);
					digits &= b >= '0' && b <= '9';
					if (digits) {
						sample = Math.min(sample * 10 + (b - '0'), Integer.MAX_VALUE);
					}
				}
				if (!digits) {
					// Python's int() also takes a sign; only a stray word fails there as here
					String text = word.toString();
					try {
						sample = Long.parseLong(text.startsWith("+") ? text.substring(1) : text);
					} catch (NumberFormatException e) {
						throw problems.at(image + ": PGM samples are not integers");
					}
				}
				largest = Math.max(largest, Math.min(sample, Integer.MAX_VALUE));
				shade[col] = (double) sample / maxval;
			}
			rows.row(row, shade, null);
		}
		return largest;
	}

	private static void readPng(Path image, Problems problems, Rows rows) throws MapException {
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
				pngRows(raster, (Node) metadata.getAsTree("javax_imageio_png_1.0"), rows);
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
	 * The samples of a PNG as stored, row by row: IHDR says the colour type and depth, PLTE and tRNS the palette and
	 * the transparent colour (pypng's {@code read}, which the Python side uses, resolves them the same way).
	 */
	private static void pngRows(Raster raster, Node tree, Rows rows) {
		Node ihdr = child(tree, "IHDR");
		String colourType = attribute(ihdr, "colorType");
		int depth = Integer.parseInt(attribute(ihdr, "bitDepth"));
		int w = raster.getWidth();
		int h = raster.getHeight();
		rows.start(w, h);
		double[] shade = new double[w];
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
			double[] alpha = null;
			if (alphas != null) {
				for (Node e = alphas.getFirstChild(); e != null; e = e.getNextSibling()) {
					palette[Integer.parseInt(attribute(e, "index"))][3] = Integer.parseInt(attribute(e, "alpha"));
				}
				alpha = new double[w];
			}
			int[] index = new int[w];
			for (int row = 0; row < h; row++) {
				raster.getSamples(0, row, w, 1, 0, index);
				for (int col = 0; col < w; col++) {
					int[] c = palette[index[col]];
					shade[col] = (c[0] + c[1] + c[2]) / 3.0 / 255.0;
					if (alpha != null) {
						alpha[col] = c[3] / 255.0;
					}
				}
				rows.row(row, shade, alpha);
			}
			return;
		}
		double full = Math.pow(2, depth) - 1;
		boolean grey = colourType.startsWith("Gray");
		int colours = grey ? 1 : 3;
		boolean alphaChannel = colourType.endsWith("Alpha");
		// one colour (or grey) stands for transparent: alpha 0 there, opaque elsewhere
		Node key = alphaChannel || trns == null ? null : child(trns, grey ? "tRNS_Grayscale" : "tRNS_RGB");
		int[] k = key == null ? null
				: grey ? new int[] { Integer.parseInt(attribute(key, "gray")) }
						: new int[] { Integer.parseInt(attribute(key, "red")),
								Integer.parseInt(attribute(key, "green")), Integer.parseInt(attribute(key, "blue")) };
		double[] alpha = alphaChannel || k != null ? new double[w] : null;
		int[][] bands = new int[colours + (alphaChannel ? 1 : 0)][w];
		for (int row = 0; row < h; row++) {
			for (int b = 0; b < bands.length; b++) {
				raster.getSamples(0, row, w, 1, b, bands[b]);
			}
			for (int col = 0; col < w; col++) {
				shade[col] = grey ? bands[0][col] / full
						: (bands[0][col] + bands[1][col] + bands[2][col]) / 3.0 / full;
				if (alphaChannel) {
					alpha[col] = bands[colours][col] / full;
				} else if (k != null) {
					boolean match = true;
					for (int b = 0; b < colours; b++) {
						match &= bands[b][col] == k[b];
					}
					alpha[col] = match ? 0.0 : 1.0;
				}
			}
			rows.row(row, shade, alpha);
		}
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

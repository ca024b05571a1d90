package org.kheperasim.sim.arena.wsu;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.cap;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.horizontal;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.vertical;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.ObjectOutputStream;
import java.io.Serializable;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Vector;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Damaged, truncated and foreign streams are refused with the reader's own error,
 * {@code file: byte N: what is wrong}, and never with another exception.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class WsuWorldDamageTest {
    private static final String FILE = "world.map";
    private static final byte[] SMALL = WsuWorldWriter.world(List.of(vertical(5, 100, 100), horizontal(6, 200, 300),
            cap(7, 300, 300)));

    private static WsuWorldException refused(byte[] bytes) {
        return assertThrows(WsuWorldException.class, () -> WsuWorld.read(bytes, FILE, "world", w -> { }));
    }

    private static WsuWorldException refusedAt(byte[] bytes, long offset, String... words) {
        WsuWorldException e = refused(bytes);
        assertEquals(offset, e.offset(), e.getMessage());
        assertTrue(e.getMessage().startsWith(FILE + ": byte " + offset + ": "), e.getMessage());
        for (String w : words) {
            assertTrue(e.getMessage().contains(w), "'" + w + "' missing from: " + e.getMessage());
        }
        return e;
    }

    private static byte[] javaStream(Object o) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeObject(o);
        }
        return bytes.toByteArray();
    }

    private static int indexOf(byte[] haystack, byte[] needle) {
        outer:
        for (int i = 0; i + needle.length <= haystack.length; i++) {
            for (int j = 0; j < needle.length; j++) {
                if (haystack[i + j] != needle[j]) {
                    continue outer;
                }
            }
            return i;
        }
        throw new AssertionError("not found");
    }

    @Test
    void everyTruncationIsTheReadersOwnError() {
        for (int n = 0; n < SMALL.length; n++) {
            byte[] cut = Arrays.copyOf(SMALL, n);
            WsuWorldException e;
            try {
                e = refused(cut);
            } catch (AssertionError a) {
                throw new AssertionError("truncated to " + n + " of " + SMALL.length + " bytes", a);
            }
            assertTrue(e.getMessage().startsWith(FILE + ": byte "), n + ": " + e.getMessage());
            assertTrue(e.offset() >= 0 && e.offset() <= n, n + ": " + e.getMessage());
        }
        WsuWorldException e = refused(Arrays.copyOf(SMALL, SMALL.length - 1));
        assertTrue(e.getMessage().contains("the file ends inside") && e.getMessage().contains("truncated"),
                e.getMessage());
    }

    @Test
    void aWrongMagicNumberOrVersionIsNamed() {
        byte[] bad = SMALL.clone();
        bad[0] = (byte) 0xCA;
        bad[1] = (byte) 0xFE;
        refusedAt(bad, 0, "0xCAFE", "not 0xACED");
        byte[] old = SMALL.clone();
        old[3] = 4;
        refusedAt(old, 2, "version 4");
    }

    @Test
    void anUnknownTagIsNamedWithItsByte() {
        byte[] bad = SMALL.clone();
        bad[4] = (byte) 0x6A; // where the Vector's TC_OBJECT is
        refusedAt(bad, 4, "0x6A is no tag");
    }

    @Test
    void aBackReferenceToAHandleNotYetGivenIsRefused() {
        byte[] bad = SMALL.clone();
        // The second Vertex refers back to the Vertex class description; point it far beyond.
        int ref = indexOf(bad, new byte[] {0x73, 0x71, 0x00, 0x7E});
        bad[ref + 4] = 0x7F;
        refusedAt(bad, ref + 1, "back-reference to handle 0x007E7F");
    }

    @Test
    void aBackReferenceToTheWrongKindOfThingIsRefused() {
        byte[] bad = SMALL.clone();
        int ref = indexOf(bad, new byte[] {0x73, 0x71, 0x00, 0x7E});
        bad[ref + 5] = 0x01; // handle 1: the string "[Ljava/lang/Object;", not a class description
        refusedAt(bad, ref + 1, "where the class of an object (a class description) was expected");
    }

    @Test
    void aWrongFieldTypeIsNotTheWsuVertex() {
        byte[] bad = SMALL.clone();
        int at = indexOf(bad, "xPos".getBytes(java.nio.charset.StandardCharsets.UTF_8));
        bad[at - 3] = 'F'; // the field's type code, before its two-byte name length
        WsuWorldException e = refused(bad);
        assertTrue(e.getMessage().contains("field 'xPos'") && e.getMessage().contains("type F, not I"), e.getMessage());
    }

    @Test
    void foreignStreamsAreNotWsuWorlds() throws Exception {
        assertTrue(refused(javaStream(Integer.valueOf(7))).getMessage()
                .contains("holds a java.lang.Integer, not a java.util.Vector"));
        assertTrue(refused(javaStream(new ArrayList<>(List.of("a", "b")))).getMessage()
                .contains("holds a java.util.ArrayList"));
        assertTrue(refused(javaStream(new HashMap<>(java.util.Map.of("k", 1)))).getMessage()
                .contains("not a WSU world file"));
        assertTrue(refused(javaStream("just a string")).getMessage().contains("holds a string"));
        WsuWorldException strings = refused(javaStream(new Vector<>(List.of("wall", "cap"))));
        assertTrue(strings.getMessage().contains("element 0 of the world's Vector is a string, not a "
                + "edu.wsu.KheperaSimulator.Vertex"), strings.getMessage());
        WsuWorldException two = refused(concat(SMALL, Arrays.copyOfRange(javaStream("more"), 4, javaStream("more").length)));
        assertTrue(two.getMessage().contains("more follows the world's java.util.Vector"), two.getMessage());
        WsuWorldException none = refusedAt(new byte[] {(byte) 0xAC, (byte) 0xED, 0, 5}, 4, "holds nothing");
        assertTrue(none.getMessage().startsWith(FILE + ": byte 4: "));
    }

    /** Writes itself with an exception in the middle, as a failed save leaves a stream. */
    static final class FailsWhenWritten implements Serializable {
        private static final long serialVersionUID = 1L;

        private void writeObject(java.io.ObjectOutputStream out) throws IOException {
            throw new java.io.NotSerializableException("the disk is full");
        }
    }

    @Test
    void aStreamRecordingAnExceptionIsRefused() throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeObject(new Vector<>(List.of(new FailsWhenWritten())));
        } catch (IOException expected) {
            // ObjectOutputStream records the exception in the stream (TC_EXCEPTION) and rethrows it.
        }
        assertTrue(refused(bytes.toByteArray()).getMessage().contains("records an exception"));
    }

    @Test
    void deepNestingIsRefusedWithoutOverflowingTheStack() throws Exception {
        Object[] nested = new Object[1];
        Object[] inner = nested;
        for (int i = 0; i < 5000; i++) {
            Object[] next = new Object[1];
            inner[0] = next;
            inner = next;
        }
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        Thread writer = new Thread(null, () -> {
            try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
                out.writeObject(nested);
            } catch (IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        }, "deep writer", 64L << 20);
        writer.start();
        writer.join();
        assertTrue(refused(bytes.toByteArray()).getMessage().contains("nested more than"));
    }

    @Test
    void hugeLengthsAreRefusedBeforeAnythingIsAllocated() throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        DataOutputStream out = new DataOutputStream(bytes);
        out.writeShort(0xACED);
        out.writeShort(5);
        out.writeByte(0x75); // TC_ARRAY
        out.writeByte(0x72); // TC_CLASSDESC "[I"
        out.writeUTF("[I");
        out.writeLong(0x4dba602676eab2a5L);
        out.writeByte(0x02);
        out.writeShort(0);
        out.writeByte(0x78);
        out.writeByte(0x70);
        int sizeAt = bytes.size();
        out.writeInt(Integer.MAX_VALUE);
        refusedAt(bytes.toByteArray(), sizeAt, "2147483647 elements");
        byte[] longString = {(byte) 0xAC, (byte) 0xED, 0, 5, 0x7C, 0x7F, 0, 0, 0, 0, 0, 0, 0};
        refusedAt(longString, 5, "a long string claims");
    }

    @Test
    void bytesChangedAnywhereGiveAnArenaOrTheReadersOwnErrorNeverAnotherException() {
        byte[] small = WsuWorldWriter.world(List.of(vertical(5, 100, 100), cap(6, 300, 300)));
        int arenas = 0;
        int refusals = 0;
        for (int i = 0; i < small.length; i++) {
            for (int variant : new int[] {0x00, 0xFF, small[i] ^ 0x01, 0x71, 0x78}) {
                byte[] changed = small.clone();
                changed[i] = (byte) variant;
                try {
                    WsuWorld.read(changed, FILE, "world", w -> { });
                    arenas++;
                } catch (WsuWorldException e) {
                    refusals++;
                    assertTrue(e.getMessage().startsWith(FILE + ": "), e.getMessage());
                } catch (RuntimeException | StackOverflowError | OutOfMemoryError e) {
                    fail("byte " + i + " set to " + variant + ": " + e, e);
                }
            }
        }
        assertTrue(arenas > 0 && refusals > 0, arenas + " read, " + refusals + " refused");
    }

    private static byte[] concat(byte[] a, byte[] b) {
        byte[] out = Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }
}

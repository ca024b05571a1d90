package org.kheperasim.sim.arena.wsu;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Writes WSU world files for the tests, by hand from the format's facts (docs: wsu-compat.md): the
 * serialization stream of a {@code java.util.Vector} of {@code edu.wsu.KheperaSimulator.Vertex}
 * objects, each with a {@code java.awt.Color}. It assigns handles as a stream writer does and
 * writes back-references for every class description, field-type string and colour it has written
 * before, so the reader meets them as it meets them in real files.
 */
public final class WsuWorldWriter {
    static final float HORIZONTAL = (float) (3 * Math.PI / 2);

    /** One object as the WSU simulator stores it: anchor top-left, px, y down. */
    public record Vertex(int id, int type, int x, int y, float theta) {
        public static Vertex vertical(int id, int x, int y) {
            return new Vertex(id, 1, x, y, 0);
        }

        public static Vertex horizontal(int id, int x, int y) {
            return new Vertex(id, 1, x, y, HORIZONTAL);
        }

        public static Vertex cap(int id, int x, int y) {
            return new Vertex(id, 2, x, y, 0);
        }

        public static Vertex ball(int id, int x, int y) {
            return new Vertex(id, 3, x, y, 0);
        }

        public static Vertex light(int id, int x, int y) {
            return new Vertex(id, 4, x, y, 0);
        }
    }

    private static final long VECTOR_UID = 0xd9977d5b803baf01L;
    private static final long OBJECT_ARRAY_UID = 0x90ce589f1073296cL;
    private static final long VERTEX_UID = -3311203242241057476L;
    private static final long COLOR_UID = 0x01a51783108f3375L;

    private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    private final DataOutputStream out = new DataOutputStream(bytes);
    private final Map<String, Integer> handlesOf = new HashMap<>();
    private int nextHandle;
    private boolean resetFirst;
    private int spareCapacity = 2;
    private boolean shareColours = true;

    /** @return this writer, which first writes a reset marker (as a stream reused for several worlds has) */
    WsuWorldWriter resetFirst() {
        resetFirst = true;
        return this;
    }

    /** @return this writer, with {@code n} unused (null) slots after the elements */
    WsuWorldWriter spareCapacity(int n) {
        spareCapacity = n;
        return this;
    }

    /** @return this writer, which writes a new Color object for every Vertex instead of back-references */
    WsuWorldWriter ownColours() {
        shareColours = false;
        return this;
    }

    /** @return the world file's bytes */
    public static byte[] world(List<Vertex> vertices) {
        return new WsuWorldWriter().write(vertices);
    }

    byte[] write(List<Vertex> vertices) {
        try {
            out.writeShort(0xACED);
            out.writeShort(5);
            if (resetFirst) {
                out.writeByte(0x79);
            }
            out.writeByte(0x73); // TC_OBJECT
            classDesc("java.util.Vector", VECTOR_UID, 0x03, new String[][] {
                {"I", "capacityIncrement"}, {"I", "elementCount"}, {"[", "elementData", "[Ljava/lang/Object;"}});
            newHandle("vector object");
            out.writeInt(0);
            out.writeInt(vertices.size());
            out.writeByte(0x75); // TC_ARRAY
            classDesc("[Ljava.lang.Object;", OBJECT_ARRAY_UID, 0x02, new String[0][]);
            newHandle("element array");
            out.writeInt(vertices.size() + spareCapacity);
            for (Vertex v : vertices) {
                vertex(v);
            }
            for (int i = 0; i < spareCapacity; i++) {
                out.writeByte(0x70); // TC_NULL
            }
            out.writeByte(0x78); // the end of Vector.writeObject's data
            return bytes.toByteArray();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private void vertex(Vertex v) throws IOException {
        out.writeByte(0x73);
        classDesc("edu.wsu.KheperaSimulator.Vertex", VERTEX_UID, 0x02, new String[][] {
            {"I", "id"}, {"I", "objType"}, {"I", "oldx"}, {"I", "oldy"}, {"F", "theta"}, {"I", "xPos"}, {"I", "yPos"},
            {"L", "robotI", "Ljava/awt/Image;"}, {"L", "vertexColor", "Ljava/awt/Color;"}});
        newHandle("vertex " + v.id());
        out.writeInt(v.id());
        out.writeInt(v.type());
        out.writeInt(v.x());
        out.writeInt(v.y());
        out.writeFloat(v.theta());
        out.writeInt(v.x());
        out.writeInt(v.y());
        out.writeByte(0x70); // no image
        int argb = switch (v.type()) {
            case 1 -> 0xffff0000;
            case 4 -> 0xffffc800;
            default -> 0xff0000ff;
        };
        String key = "colour " + argb;
        if (shareColours && handlesOf.containsKey(key)) {
            reference(key);
            return;
        }
        out.writeByte(0x73);
        classDesc("java.awt.Color", COLOR_UID, 0x02, new String[][] {
            {"F", "falpha"}, {"I", "value"}, {"L", "cs", "Ljava/awt/color/ColorSpace;"}, {"[", "frgbvalue", "[F"},
            {"[", "fvalue", "[F"}});
        handlesOf.put(key, nextHandle++);
        out.writeFloat(0);
        out.writeInt(argb);
        out.writeByte(0x70);
        out.writeByte(0x70);
        out.writeByte(0x70);
    }

    /** A class description, or a back-reference to the one written before. */
    private void classDesc(String name, long uid, int flags, String[][] fields) throws IOException {
        if (handlesOf.containsKey("class " + name)) {
            reference("class " + name);
            return;
        }
        out.writeByte(0x72); // TC_CLASSDESC
        out.writeUTF(name);
        out.writeLong(uid);
        handlesOf.put("class " + name, nextHandle++);
        out.writeByte(flags);
        out.writeShort(fields.length);
        for (String[] f : fields) {
            out.writeByte(f[0].charAt(0));
            out.writeUTF(f[1]);
            if (f.length > 2) {
                string(f[2]);
            }
        }
        out.writeByte(0x78); // no class annotations
        out.writeByte(0x70); // superclass: none serializable
    }

    private void string(String s) throws IOException {
        if (handlesOf.containsKey("string " + s)) {
            reference("string " + s);
            return;
        }
        out.writeByte(0x74); // TC_STRING
        out.writeUTF(s);
        handlesOf.put("string " + s, nextHandle++);
    }

    private void reference(String key) throws IOException {
        out.writeByte(0x71); // TC_REFERENCE
        out.writeInt(0x7E0000 + handlesOf.get(key));
    }

    private void newHandle(String what) {
        handlesOf.put(what, nextHandle++);
    }
}

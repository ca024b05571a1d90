package org.kheperasim.sim.arena.wsu;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.kheperasim.sim.arena.wsu.StreamModel.ClassDesc;
import org.kheperasim.sim.arena.wsu.StreamModel.FieldDesc;
import org.kheperasim.sim.arena.wsu.StreamModel.JavaArray;
import org.kheperasim.sim.arena.wsu.StreamModel.JavaObject;
import org.kheperasim.sim.arena.wsu.StreamModel.Top;
import org.kheperasim.sim.arena.wsu.StreamModel.Value;

/**
 * The objects of a WSU world, read from its parsed serialization stream: one
 * {@code java.util.Vector} whose first {@code elementCount} elements are
 * {@code edu.wsu.KheperaSimulator.Vertex} objects. Each Vertex gives its id, kind, anchor (top-left,
 * pixels of the 500 x 500 panel, y down) and angle; its colour and image are ignored.
 */
final class WsuWorldObjects {
    static final String VECTOR = "java.util.Vector";
    static final String VERTEX = "edu.wsu.KheperaSimulator.Vertex";
    /** The serialVersionUID of the Vertex class every known world file holds. */
    static final long VERTEX_UID = -3311203242241057476L;

    /**
     * One object of the world, as stored.
     *
     * @param id     its id (unique, from 5 up)
     * @param type   1 wall, 2 cap, 3 ball, 4 light
     * @param x      anchor, px from the panel's left
     * @param y      anchor, px from the panel's top
     * @param theta  angle, rad (0 for a vertical wall)
     * @param offset byte offset of the Vertex in the file, for messages
     */
    record WsuObject(int id, int type, int x, int y, float theta, long offset) {
        static final int WALL = 1;
        static final int CAP = 2;
        static final int BALL = 3;
        static final int LIGHT = 4;
    }

    private final String source;

    private WsuWorldObjects(String source) {
        this.source = source;
    }

    /**
     * @param contents the stream's top-level contents
     * @param source   the file's name, for messages
     * @param warnings where to say what is odd but readable
     * @return the world's objects, in the file's order
     * @throws WsuWorldException when the stream is not a WSU world
     */
    static List<WsuObject> read(List<Top> contents, String source, Consumer<String> warnings) {
        return new WsuWorldObjects(source).objects(contents, warnings);
    }

    private WsuWorldException error(long offset, String what) {
        return new WsuWorldException(source, offset, what);
    }

    private List<WsuObject> objects(List<Top> contents, Consumer<String> warnings) {
        if (contents.isEmpty()) {
            throw error(4, "the stream holds nothing; a WSU world file holds one " + VECTOR + " of " + VERTEX
                    + " objects");
        }
        Top top = contents.get(0);
        if (!(top.value() instanceof JavaObject vector) || !vector.desc.name.equals(VECTOR)) {
            throw error(top.offset(), "the stream holds " + describe(top.value()) + ", not a " + VECTOR
                    + " of " + VERTEX + " objects: it is not a WSU world file");
        }
        if (contents.size() > 1) {
            throw error(contents.get(1).offset(), "more follows the world's " + VECTOR + " (" + describe(contents.get(1)
                    .value()) + "): a WSU world file holds one Vector and nothing else");
        }
        int count = intField(vector, "elementCount", VECTOR);
        Value data = field(vector, "elementData", "[Ljava/lang/Object;", VECTOR);
        if (!(data.value() instanceof JavaArray array)) {
            throw error(data.offset(), "the Vector's elementData is " + describe(data.value()) + ", not an array");
        }
        if (count < 0 || count > array.elements().size()) {
            throw error(vector.offset, "the Vector says it holds " + count + " elements, but its array has room for "
                    + array.elements().size() + ": the file is damaged");
        }
        List<WsuObject> objects = new ArrayList<>();
        boolean uidWarned = false;
        for (int i = 0; i < count; i++) {
            Object element = array.elements().get(i);
            if (!(element instanceof JavaObject vertex) || !vertex.desc.name.equals(VERTEX)) {
                throw error(array.offset(),
                        "element " + i + " of the world's Vector is " + describe(element) + ", not a "
                        + VERTEX + ": it is not a WSU world file, or it is damaged");
            }
            if (vertex.desc.serialVersionUid != VERTEX_UID && !uidWarned) {
                uidWarned = true;
                warnings.accept(String.format("the Vertex class has serialVersionUID %d, not %d as in the WSU"
                        + " simulator's saved worlds; read anyway", vertex.desc.serialVersionUid, VERTEX_UID));
            }
            objects.add(new WsuObject(intField(vertex, "id", VERTEX), intField(vertex, "objType", VERTEX),
                    intField(vertex, "xPos", VERTEX), intField(vertex, "yPos", VERTEX),
                    (Float) field(vertex, "theta", "F", VERTEX).value(), vertex.offset));
        }
        return objects;
    }

    private int intField(JavaObject o, String name, String className) {
        return (Integer) field(o, name, "I", className).value();
    }

    /** A field's value, after checking the class declares it with that type. */
    private Value field(JavaObject o, String name, String descriptor, String className) {
        ClassDesc declaring = null;
        for (ClassDesc c = o.desc; c != null && declaring == null; c = c.superDesc) {
            if (c.field(name) != null) {
                declaring = c;
            }
        }
        if (declaring == null) {
            throw error(o.desc.offset, className + " in this file has no field '" + name + "' (it has "
                    + fieldList(o.desc) + "): it is not the WSU simulator's " + className);
        }
        FieldDesc f = declaring.field(name);
        if (!f.descriptor().equals(descriptor)) {
            throw error(o.desc.offset, "field '" + name + "' of " + className + " has type " + f.descriptor()
                    + ", not " + descriptor + ": it is not the WSU simulator's " + className);
        }
        Value v = o.field(name);
        if (v == null) {
            throw error(o.offset, "the " + className + " has no value for its field '" + name + "' (its class is not"
                    + " marked serializable): the file is damaged");
        }
        return v;
    }

    private static String fieldList(ClassDesc desc) {
        List<String> names = new ArrayList<>();
        for (ClassDesc c = desc; c != null; c = c.superDesc) {
            for (FieldDesc f : c.fields) {
                names.add(f.name() + ":" + f.descriptor());
            }
        }
        return names.isEmpty() ? "no fields" : String.join(", ", names);
    }

    private static String describe(Object o) {
        if (o == null) {
            return "null";
        }
        if (o instanceof String) {
            return "a string";
        }
        return o.toString();
    }
}

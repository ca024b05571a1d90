package org.kheperasim.sim.arena.wsu;

import static java.io.ObjectStreamConstants.SC_BLOCK_DATA;
import static java.io.ObjectStreamConstants.SC_ENUM;
import static java.io.ObjectStreamConstants.SC_EXTERNALIZABLE;
import static java.io.ObjectStreamConstants.SC_SERIALIZABLE;
import static java.io.ObjectStreamConstants.SC_WRITE_METHOD;
import static java.io.ObjectStreamConstants.STREAM_MAGIC;
import static java.io.ObjectStreamConstants.STREAM_VERSION;
import static java.io.ObjectStreamConstants.TC_ARRAY;
import static java.io.ObjectStreamConstants.TC_BLOCKDATA;
import static java.io.ObjectStreamConstants.TC_BLOCKDATALONG;
import static java.io.ObjectStreamConstants.TC_CLASS;
import static java.io.ObjectStreamConstants.TC_CLASSDESC;
import static java.io.ObjectStreamConstants.TC_ENDBLOCKDATA;
import static java.io.ObjectStreamConstants.TC_ENUM;
import static java.io.ObjectStreamConstants.TC_EXCEPTION;
import static java.io.ObjectStreamConstants.TC_LONGSTRING;
import static java.io.ObjectStreamConstants.TC_NULL;
import static java.io.ObjectStreamConstants.TC_OBJECT;
import static java.io.ObjectStreamConstants.TC_PROXYCLASSDESC;
import static java.io.ObjectStreamConstants.TC_REFERENCE;
import static java.io.ObjectStreamConstants.TC_RESET;
import static java.io.ObjectStreamConstants.TC_STRING;
import static java.io.ObjectStreamConstants.baseWireHandle;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.kheperasim.sim.arena.wsu.StreamModel.BlockData;
import org.kheperasim.sim.arena.wsu.StreamModel.ClassDesc;
import org.kheperasim.sim.arena.wsu.StreamModel.FieldDesc;
import org.kheperasim.sim.arena.wsu.StreamModel.JavaArray;
import org.kheperasim.sim.arena.wsu.StreamModel.JavaClass;
import org.kheperasim.sim.arena.wsu.StreamModel.JavaEnum;
import org.kheperasim.sim.arena.wsu.StreamModel.JavaObject;
import org.kheperasim.sim.arena.wsu.StreamModel.Top;
import org.kheperasim.sim.arena.wsu.StreamModel.Value;

/**
 * A strict reader of the Java Object Serialization Stream Protocol (version 5, the grammar of the
 * Java Object Serialization Specification, section 6.4) that instantiates nothing: it turns the
 * stream into {@link StreamModel} data, never into objects of the classes it names, so a hostile
 * file can do no more than fail to parse. Class descriptions, handles and back-references, resets,
 * strings, arrays, enums, class objects and block data are read; a stream recording an exception,
 * an externalizable class written without block data, or anything the grammar does not allow is
 * refused with a {@link WsuWorldException} naming the byte.
 */
final class SerialStreamParser {
    /** Deeper nesting than this is refused (the stack must not overflow on a hostile file). */
    static final int MAX_DEPTH = 200;

    private static final String PRIMITIVE_CODES = "BCDFIJSZ";

    private final StreamInput in;
    private final List<Object> handles = new ArrayList<>();
    private int depth;

    private SerialStreamParser(StreamInput in) {
        this.in = in;
    }

    /**
     * @param bytes  a whole file
     * @param source its name, for errors
     * @return the stream's top-level contents, in order (resets between them consumed)
     * @throws WsuWorldException when the bytes are not a well-formed serialization stream
     */
    static List<Top> parse(byte[] bytes, String source) {
        return new SerialStreamParser(new StreamInput(bytes, source)).stream();
    }

    private List<Top> stream() {
        int magic = in.u2("the stream's magic number");
        if (magic != (STREAM_MAGIC & 0xFFFF)) {
            throw in.error(0, String.format("the file starts with 0x%04X, not 0xACED: it is not a Java serialization"
                    + " stream, so not a WSU world file", magic));
        }
        int version = in.u2("the stream's version");
        if (version != STREAM_VERSION) {
            throw in.error(2, "serialization stream version " + version + "; only version " + STREAM_VERSION
                    + " (every Java since 1.2) is read");
        }
        List<Top> contents = new ArrayList<>();
        while (!in.atEnd()) {
            if (in.peek("the stream's contents") == TC_RESET) {
                in.u1("a reset");
                handles.clear();
                continue;
            }
            long at = in.offset();
            contents.add(new Top(content(), at));
        }
        return contents;
    }

    /** An object or block data. */
    private Object content() {
        int tc = in.peek("an object or block data");
        return tc == TC_BLOCKDATA || tc == TC_BLOCKDATALONG ? blockData() : object();
    }

    private Object object() {
        long at = in.offset();
        int tc = in.u1("an object");
        if (++depth > MAX_DEPTH) {
            throw in.error(at, "objects nested more than " + MAX_DEPTH + " deep: no WSU world is like this;"
                    + " the file is damaged or not a world file");
        }
        try {
            return switch (tc) {
                case TC_NULL -> null;
                case TC_REFERENCE -> reference(at);
                case TC_CLASSDESC, TC_PROXYCLASSDESC -> newClassDesc(tc, at);
                case TC_OBJECT -> newObject(at);
                case TC_STRING -> assign(in.utf("a string"));
                case TC_LONGSTRING -> assign(in.longUtf("a long string"));
                case TC_ARRAY -> newArray(at);
                case TC_CLASS -> assign(new JavaClass(nonNullClassDesc("the class of a class object")));
                case TC_ENUM -> newEnum(at);
                case TC_EXCEPTION -> throw in.error(at, "the stream records an exception (TC_EXCEPTION): the program"
                        + " that wrote it failed while saving, so the file is incomplete");
                case TC_RESET -> throw in.error(at, "a reset (TC_RESET) inside an object: the stream is damaged");
                case TC_ENDBLOCKDATA -> throw in.error(at, "an end of block data (0x78) where an object was expected:"
                        + " the stream is damaged");
                case TC_BLOCKDATA, TC_BLOCKDATALONG -> throw in.error(at, "block data where an object was expected:"
                        + " the stream is damaged");
                default -> throw in.error(at, String.format("0x%02X is no tag of the serialization stream (an object"
                        + " was expected here): the file is damaged", tc));
            };
        } finally {
            depth--;
        }
    }

    private <T> T assign(T value) {
        handles.add(value);
        return value;
    }

    private Object reference(long at) {
        int handle = in.s4("a back-reference's handle");
        long index = (long) handle - baseWireHandle;
        if (index < 0 || index >= handles.size()) {
            throw in.error(at, String.format("a back-reference to handle 0x%08X, but only handles 0x%08X..0x%08X exist"
                    + " at this point: the stream is damaged", handle, baseWireHandle,
                    baseWireHandle + handles.size() - 1));
        }
        return handles.get((int) index);
    }

    /** {@code classDesc}: a new class description, a reference to one, or null. */
    private ClassDesc classDesc(String what) {
        long at = in.offset();
        int tc = in.peek(what);
        if (tc != TC_CLASSDESC && tc != TC_PROXYCLASSDESC && tc != TC_NULL && tc != TC_REFERENCE) {
            throw in.error(at, String.format("tag 0x%02X where %s (a class description) was expected: the stream is"
                    + " damaged", tc, what));
        }
        Object o = object();
        if (o != null && !(o instanceof ClassDesc)) {
            throw in.error(at, "a back-reference to " + describe(o) + " where " + what
                    + " (a class description) was expected: the stream is damaged");
        }
        return (ClassDesc) o;
    }

    private ClassDesc nonNullClassDesc(String what) {
        long at = in.offset();
        ClassDesc desc = classDesc(what);
        if (desc == null) {
            throw in.error(at, "null where " + what + " was expected: the stream is damaged");
        }
        return desc;
    }

    private ClassDesc newClassDesc(int tc, long at) {
        if (tc == TC_PROXYCLASSDESC) {
            ClassDesc desc = assign(new ClassDesc("a dynamic proxy", 0, at));
            int count = in.s4("the number of a proxy's interfaces");
            if (count < 0 || count > in.remaining()) {
                throw in.error(at, "a proxy class with " + count + " interfaces: the stream is damaged");
            }
            for (int i = 0; i < count; i++) {
                in.utf("a proxy's interface name");
            }
            desc.flags = SC_SERIALIZABLE;
            annotations(desc.name, new ArrayList<>());
            desc.superDesc = classDesc("the proxy's superclass description");
            return desc;
        }
        String name = in.utf("a class name");
        long uid = in.s8("the serialVersionUID of " + name);
        ClassDesc desc = assign(new ClassDesc(name, uid, at));
        long flagsAt = in.offset();
        desc.flags = in.u1("the flags of " + name);
        boolean serializable = (desc.flags & SC_SERIALIZABLE) != 0;
        boolean externalizable = (desc.flags & SC_EXTERNALIZABLE) != 0;
        if (serializable && externalizable) {
            throw in.error(flagsAt, "class " + name + " is marked both serializable and externalizable: the stream is"
                    + " damaged");
        }
        long countAt = in.offset();
        int count = (short) in.u2("the number of fields of " + name);
        if (count < 0 || count > in.remaining() / 3) {
            throw in.error(countAt, "class " + name + " claims " + count + " fields: the stream is damaged");
        }
        for (int i = 0; i < count; i++) {
            desc.fields.add(fieldDesc(name));
        }
        annotations(name, new ArrayList<>());
        desc.superDesc = classDesc("the superclass description of " + name);
        return desc;
    }

    private FieldDesc fieldDesc(String owner) {
        long at = in.offset();
        char type = (char) in.u1("a field type of " + owner);
        String name = in.utf("a field name of " + owner);
        if (PRIMITIVE_CODES.indexOf(type) >= 0) {
            return new FieldDesc(type, name, null);
        }
        if (type != 'L' && type != '[') {
            throw in.error(at, String.format(
                    "field %s of %s has type code 0x%02X, which is none of B C D F I J S Z L [:"
                    + " the stream is damaged", name, owner, (int) type));
        }
        long typeAt = in.offset();
        Object className = object();
        if (!(className instanceof String s)) {
            throw in.error(typeAt, "the type of field " + name + " of " + owner + " is " + describe(className)
                    + ", not a string: the stream is damaged");
        }
        return new FieldDesc(type, name, s);
    }

    /** {@code classAnnotation} or {@code objectAnnotation}: contents up to the end-of-block-data tag. */
    private void annotations(String owner, List<Object> into) {
        while (true) {
            if (in.peek("the annotations of " + owner) == TC_ENDBLOCKDATA) {
                in.u1("an end of block data");
                return;
            }
            into.add(content());
        }
    }

    private BlockData blockData() {
        long at = in.offset();
        int tc = in.u1("block data");
        int size = tc == TC_BLOCKDATA ? in.u1("the size of block data") : in.s4("the size of block data");
        if (size < 0) {
            throw in.error(at, "block data of " + size + " bytes: the stream is damaged");
        }
        return new BlockData(in.bytes(size, "block data"));
    }

    private JavaObject newObject(long at) {
        ClassDesc desc = nonNullClassDesc("the class of an object");
        if ((desc.flags & SC_ENUM) != 0) {
            throw in.error(at, "an object of the enum class " + desc.name + " written as a plain object: the stream is"
                    + " damaged");
        }
        JavaObject object = assign(new JavaObject(desc, at));
        if ((desc.flags & SC_EXTERNALIZABLE) != 0) {
            if ((desc.flags & SC_BLOCK_DATA) == 0) {
                throw in.error(at, "class " + desc.name + " was written by the old protocol 1 for externalizable"
                        + " classes, which only the class itself can read; it is not part of a WSU world");
            }
            annotations(desc.name, object.annotations);
            return object;
        }
        Deque<ClassDesc> hierarchy = new ArrayDeque<>();
        for (ClassDesc c = desc; c != null; c = c.superDesc) {
            if (hierarchy.contains(c) || hierarchy.size() > MAX_DEPTH) {
                throw in.error(c.offset, "the superclasses of " + desc.name + " form a loop: the stream is damaged");
            }
            hierarchy.push(c);
        }
        for (ClassDesc c : hierarchy) { // from the topmost superclass down
            if ((c.flags & SC_SERIALIZABLE) == 0) {
                continue;
            }
            object.fields.put(c.name, fieldValues(c));
            if ((c.flags & SC_WRITE_METHOD) != 0) {
                annotations(c.name, object.annotations);
            }
        }
        return object;
    }

    /** A class's field values: all primitive values first, then the references, each in description order. */
    private Map<String, Value> fieldValues(ClassDesc c) {
        Map<String, Value> values = new LinkedHashMap<>();
        for (FieldDesc f : c.fields) {
            if (f.primitive()) {
                long at = in.offset();
                values.put(f.name(), new Value(primitive(f.type(), "field " + f.name() + " of " + c.name), at));
            }
        }
        for (FieldDesc f : c.fields) {
            if (!f.primitive()) {
                long at = in.offset();
                values.put(f.name(), new Value(object(), at));
            }
        }
        return values;
    }

    private Object primitive(char type, String what) {
        return switch (type) {
            case 'B' -> (byte) in.u1(what);
            case 'C' -> (char) in.u2(what);
            case 'D' -> Double.longBitsToDouble(in.s8(what));
            case 'F' -> Float.intBitsToFloat(in.s4(what));
            case 'I' -> in.s4(what);
            case 'J' -> in.s8(what);
            case 'S' -> (short) in.u2(what);
            case 'Z' -> in.u1(what) != 0;
            default -> throw new IllegalArgumentException("not a primitive type code: " + type);
        };
    }

    private static int width(char type) {
        return switch (type) {
            case 'B', 'Z' -> 1;
            case 'C', 'S' -> 2;
            case 'F', 'I' -> 4;
            case 'D', 'J' -> 8;
            default -> 1; // a reference takes at least its one-byte tag
        };
    }

    private JavaArray newArray(long at) {
        ClassDesc desc = nonNullClassDesc("the class of an array");
        if (desc.name.length() < 2 || desc.name.charAt(0) != '[') {
            throw in.error(at, "an array of class " + desc.name
                    + ", which is not an array class: the stream is damaged");
        }
        char element = desc.name.charAt(1);
        boolean primitive = PRIMITIVE_CODES.indexOf(element) >= 0;
        if (!primitive && element != 'L' && element != '[') {
            throw in.error(at, "an array of class " + desc.name
                    + ", which names no element type: the stream is damaged");
        }
        List<Object> elements = new ArrayList<>();
        JavaArray array = assign(new JavaArray(desc, at, elements));
        long sizeAt = in.offset();
        int size = in.s4("the length of an array");
        if (size < 0 || (long) size * width(element) > in.remaining()) {
            throw in.error(sizeAt, "an array " + desc.name + " of " + size + " elements, but " + in.remaining()
                    + " bytes are left: the file is damaged or truncated");
        }
        for (int i = 0; i < size; i++) {
            elements.add(primitive ? primitive(element, "element " + i + " of an array") : object());
        }
        return array;
    }

    private JavaEnum newEnum(long at) {
        ClassDesc desc = nonNullClassDesc("the class of an enum constant");
        int handle = handles.size();
        handles.add(null); // the constant's handle comes before its name
        long nameAt = in.offset();
        Object name = object();
        if (!(name instanceof String s)) {
            throw in.error(nameAt, "the name of an enum constant of " + desc.name + " is " + describe(name)
                    + ", not a string: the stream is damaged");
        }
        JavaEnum constant = new JavaEnum(desc, s);
        handles.set(handle, constant);
        return constant;
    }

    private static String describe(Object o) {
        if (o == null) {
            return "null";
        }
        if (o instanceof String s) {
            return "the string \"" + (s.length() > 40 ? s.substring(0, 40) + "…" : s) + "\"";
        }
        if (o instanceof ClassDesc c) {
            return "the class description of " + c.name;
        }
        return o.toString();
    }
}

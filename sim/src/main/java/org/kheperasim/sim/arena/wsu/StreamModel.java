package org.kheperasim.sim.arena.wsu;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What a Java serialization stream holds, as plain data: class descriptions, objects as their
 * field values, arrays, enums, class objects and block data. Nothing here is ever turned into an
 * instance of the class it describes. Strings are {@code String}s and a null reference is
 * {@code null}.
 */
final class StreamModel {
    private StreamModel() {
    }

    /**
     * One field of a class description.
     *
     * @param type      the type code: {@code B C D F I J S Z} for primitives, {@code L} or {@code [} for references
     * @param name      the field's name
     * @param className for a reference, its type in descriptor form (e.g. {@code Ljava/awt/Color;}); else null
     */
    record FieldDesc(char type, String name, String className) {
        boolean primitive() {
            return type != 'L' && type != '[';
        }

        /** @return the type as a descriptor, e.g. {@code I} or {@code [Ljava/lang/Object;} */
        String descriptor() {
            return primitive() ? String.valueOf(type) : className;
        }
    }

    /** A class description ({@code TC_CLASSDESC} or {@code TC_PROXYCLASSDESC}). Filled in as it is read. */
    static final class ClassDesc {
        final String name;
        final long serialVersionUid;
        final long offset;
        int flags;
        final List<FieldDesc> fields = new ArrayList<>();
        ClassDesc superDesc;

        ClassDesc(String name, long serialVersionUid, long offset) {
            this.name = name;
            this.serialVersionUid = serialVersionUid;
            this.offset = offset;
        }

        /** @return the field of that name, or null */
        FieldDesc field(String fieldName) {
            for (FieldDesc f : fields) {
                if (f.name().equals(fieldName)) {
                    return f;
                }
            }
            return null;
        }

        @Override
        public String toString() {
            return name;
        }
    }

    /**
     * A field's value and where it starts in the file.
     *
     * @param value  a boxed primitive, a String, null, or another model value
     * @param offset byte offset of the value
     */
    record Value(Object value, long offset) {
    }

    /** An object ({@code TC_OBJECT}): per class of its hierarchy, the field values and annotations. */
    static final class JavaObject {
        final ClassDesc desc;
        final long offset;
        /** Field values by class name, then field name; the most derived class last. */
        final Map<String, Map<String, Value>> fields = new LinkedHashMap<>();
        /** Objects and block data written by a class's own writeObject or writeExternal. */
        final List<Object> annotations = new ArrayList<>();

        JavaObject(ClassDesc desc, long offset) {
            this.desc = desc;
            this.offset = offset;
        }

        /** @return the value of the field of that name, searched from the most derived class up; or null */
        Value field(String name) {
            Value found = null;
            for (Map<String, Value> perClass : fields.values()) {
                Value v = perClass.get(name);
                if (v != null) {
                    found = v;
                }
            }
            return found;
        }

        @Override
        public String toString() {
            return "a " + desc.name;
        }
    }

    /**
     * An array ({@code TC_ARRAY}).
     *
     * @param desc     its class description (name starting with {@code [})
     * @param offset   byte offset of the array
     * @param elements boxed primitives or references, in order
     */
    record JavaArray(ClassDesc desc, long offset, List<Object> elements) {
        @Override
        public String toString() {
            return "an array " + desc.name;
        }
    }

    /** An enum constant ({@code TC_ENUM}). */
    record JavaEnum(ClassDesc desc, String constant) {
        @Override
        public String toString() {
            return "the enum constant " + desc.name + "." + constant;
        }
    }

    /** A class object ({@code TC_CLASS}). */
    record JavaClass(ClassDesc desc) {
        @Override
        public String toString() {
            return "the class " + desc.name;
        }
    }

    /** Raw bytes written by a class's own serialization code ({@code TC_BLOCKDATA}). */
    record BlockData(byte[] bytes) {
        @Override
        public String toString() {
            return bytes.length + " bytes of block data";
        }
    }

    /**
     * A top-level item of the stream.
     *
     * @param value  what was read
     * @param offset where it starts
     */
    record Top(Object value, long offset) {
    }
}

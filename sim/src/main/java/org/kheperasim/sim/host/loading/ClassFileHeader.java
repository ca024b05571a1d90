package org.kheperasim.sim.host.loading;

import org.objectweb.asm.Opcodes;

/** The first check of a controller's class file: is it one, and can the rewriter and this JVM read it? */
final class ClassFileHeader {
    /**
     * The newest class file version this rewriter accepts: what both ASM 9.8 (up to Java 25) and
     * the running JVM can read.
     */
    private static final int NEWEST_VERSION = Math.min(Opcodes.V25, 44 + Runtime.version().feature());

    private static final int CLASS_FILE_MAGIC = 0xCAFEBABE;

    private ClassFileHeader() {
    }

    /** Reject what is not a class file, or one too new to read, with a message a student can act on. */
    static void check(byte[] classFile) {
        check(classFile, null);
    }

    /**
     * @param where the file, to begin the message with, or null
     * @throws ClassFormatError when it is no class file
     * @throws UnsupportedClassVersionError when it was compiled for a newer Java than the simulator reads
     */
    static void check(byte[] classFile, String where) {
        String prefix = where == null ? "" : where + ": ";
        if (classFile.length < 8 || readInt(classFile, 0) != CLASS_FILE_MAGIC) {
            throw new ClassFormatError(prefix + "not a class file (it does not start with 0xCAFEBABE); compile the"
                    + " source again with `javac --release 17`");
        }
        int major = ((classFile[6] & 0xFF) << 8) | (classFile[7] & 0xFF);
        if (major > NEWEST_VERSION) {
            int running = Runtime.version().feature();
            String newest = NEWEST_VERSION - 44 == running ? "this Java " + running
                    : "Java " + (NEWEST_VERSION - 44) + ", the newest this simulator reads";
            throw new UnsupportedClassVersionError(prefix + "compiled for Java " + (major - 44)
                    + " (class file version "
                    + major + "), newer than " + newest + "; compile it with `--release 17`");
        }
    }

    /** @return the message of a class file that ASM cannot read, beginning with {@code where} when given */
    static String malformed(String where, RuntimeException e) {
        return (where == null ? "" : where + ": ") + "not a well-formed class file (" + e
                + "); compile the source again with `javac --release 17`";
    }

    private static int readInt(byte[] b, int offset) {
        return ((b[offset] & 0xFF) << 24) | ((b[offset + 1] & 0xFF) << 16)
                | ((b[offset + 2] & 0xFF) << 8) | (b[offset + 3] & 0xFF);
    }

}

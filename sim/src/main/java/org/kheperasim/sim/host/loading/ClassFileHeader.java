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
        if (classFile.length < 8 || readInt(classFile, 0) != CLASS_FILE_MAGIC) {
            throw new ClassFormatError("not a class file (it does not start with 0xCAFEBABE)");
        }
        int major = ((classFile[6] & 0xFF) << 8) | (classFile[7] & 0xFF);
        if (major > NEWEST_VERSION) {
            throw new UnsupportedClassVersionError("compiled for Java " + (major - 44) + " (class file version "
                    + major + "), but the simulator loads classes up to Java " + (NEWEST_VERSION - 44)
                    + ": compile it with --release 17");
        }
    }

    private static int readInt(byte[] b, int offset) {
        return ((b[offset] & 0xFF) << 24) | ((b[offset + 1] & 0xFF) << 16)
                | ((b[offset + 2] & 0xFF) << 8) | (b[offset + 3] & 0xFF);
    }

}

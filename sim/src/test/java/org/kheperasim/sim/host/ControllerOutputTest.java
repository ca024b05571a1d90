package org.kheperasim.sim.host;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A line printed whole (which reaches the console without being encoded and decoded) is the same line
 * its bytes make: a trailing carriage return taken off, a lone surrogate as {@code ?}, a pending part of
 * a line joined, a long line cut at {@link ControllerOutput#MAX_LINE} bytes.
 */
class ControllerOutputTest {
    @Test
    void wholeLinesAreTheLinesTheirBytesMake() {
        ByteArrayOutputStream real = new ByteArrayOutputStream();
        PrintStream old = System.out;
        try {
            System.setOut(new PrintStream(real, true, StandardCharsets.UTF_8));
            PrintStream out = ControllerOutput.out();
            out.println("plain");
            out.println("dos\r");
            out.println("lone \uD800 surrogate");
            out.print("pen");
            out.println("ding");
            out.println(42);
            out.println((Object) null);
            out.println('c');
            out.println("two\nlines");
            out.println("é".repeat(5000)); // 10,000 bytes: cut at 8192
            out.println("after");
        } finally {
            System.setOut(old);
        }
        List<String> lines = real.toString(StandardCharsets.UTF_8).lines().toList();
        assertEquals(List.of("plain", "dos", "lone ? surrogate", "pending", "42", "null", "c", "two", "lines",
                "é".repeat(4096), "é".repeat(904), "after"), lines);
    }
}

package org.kheperasim.link.tool;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.link.cli.Main;

/** khepera-link's command line: help, version, exit codes and number checks, without a robot. */
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class KheperaLinkCommandLineTest {
    private String out;
    private String err;

    private int main(String... args) {
        StringWriter o = new StringWriter();
        StringWriter e = new StringWriter();
        int code = Main.execute(args, new ByteArrayInputStream(new byte[0]), new PrintWriter(o), new PrintWriter(e));
        out = o.toString();
        err = e.toString();
        return code;
    }

    @Test
    void everyCommandsHelpExitsZeroAndEndsWithTheExitCodes() {
        for (String cmd : new String[] {"run", "check", "console", "bench", "ports"}) {
            assertEquals(0, main(cmd, "--help"), cmd + ": " + out + err);
            assertTrue(out.replaceAll("\\s+", " ").contains(ExitCodes.HELP), cmd + ": " + out);
        }
        assertEquals(0, main("run", "--help"));
        for (String name : new BundledControllers()) {
            assertTrue(out.contains(name), name + " missing from run --help: " + out);
        }
        assertTrue(out.contains("CapGatherer"), out);
    }

    @Test
    void versionComesFromTheBuild() {
        assertEquals(0, main("--version"));
        assertTrue(out.startsWith("khepera-link " + ToolVersion.version()), out);
        assertTrue(ToolVersion.version().matches("\\d+\\.\\d+\\.\\d+.*"), ToolVersion.version());
    }

    @Test
    void badNumbersAreRefusedWithTheToolsPrefixAndExitTwo() {
        assertEquals(2, main("run", "--port", "/dev/null", "--controller", "WallFollower", "--baud", "0x1p10"));
        assertTrue(err.startsWith("khepera-link: error: ") && err.contains("not a Khepera line speed"), err);
        assertEquals(2, main("run", "--port", "/dev/null", "--controller", "WallFollower", "--baud", "12345"));
        for (String seconds : new String[] {"-1", "0", "NaN", "Infinity", "1e400", "0x10"}) {
            assertEquals(2, main("run", "--port", "/dev/null", "--controller", "WallFollower", "--seconds", seconds), seconds);
            assertTrue(err.startsWith("khepera-link: error: Invalid value for option '--seconds'"), err);
        }
        assertEquals(2, main("run", "--port", "/dev/null", "--controller", "WallFollower", "--timeout", "0"));
        assertEquals(2, main("run", "--port", "/dev/null", "--controller", "WallFollower", "--retries", "-1"));
        assertEquals(2, main("bench", "--port", "/dev/null", "--seconds", "NaN"));
        assertEquals(2, main("run", "--controller", "WallFollower"));
        assertTrue(err.contains("Missing required option: '--port=PATH'") && err.contains("See 'khepera-link run --help'"), err);
    }
}

package org.kheperasim.sim.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** Issue 35 item 6: control characters shown escaped, reversibly; CSV cells never formulas. */
class ShownTest {
    /** Every character a terminal or renderer acts on, and none it shows. */
    @Test
    void escapesC0DelC1BidiAndSeparatorsOnly() {
        for (char c = 0; c < 0x3000; c++) {
            boolean control = c < 0x20 || (c >= 0x7f && c <= 0x9f) || c == 0x061c || c == 0x200e || c == 0x200f
                    || (c >= 0x2028 && c <= 0x202e) || (c >= 0x2066 && c <= 0x2069);
            assertEquals(control, Shown.isControl(c), Integer.toHexString(c));
            String shown = Shown.line("a" + c + "b");
            for (char s : shown.toCharArray()) {
                assertFalse(Shown.isControl(s), Integer.toHexString(c) + " -> " + shown);
            }
        }
        assertEquals("\\e[2J\\r\\x07\\x00\\u202e\\n\\t\\x7f\\x85\\\\", Shown.line("\u001b[2J\r\u0007\u0000\u202e\n\t\u007f\u0085\\"));
        assertEquals("plain text, é ü ß 中文", Shown.line("plain text, é ü ß 中文"));
    }

    @Test
    void theEscapesGiveTheTextBack() {
        SplittableRandom r = new SplittableRandom(35);
        for (int n = 0; n < 2000; n++) {
            StringBuilder s = new StringBuilder();
            for (int i = r.nextInt(20); i > 0; i--) {
                s.append(r.nextInt(4) == 0 ? (char) r.nextInt(0x30) : r.nextBoolean() ? '\\' : (char) r.nextInt(0x2100));
            }
            String text = s.toString();
            assertEquals(text, Shown.unescape(Shown.line(text)));
            assertEquals(text, Shown.fromCsvCell(unquote(Shown.csvCell(text))));
        }
    }

    @Test
    void anErrorMessageKeepsItsBackslashes() {
        assertEquals("no arena file 'C:\\Users\\me\\x.arena'\\n\\e", Shown.visible("no arena file 'C:\\Users\\me\\x.arena'\n\u001b"));
    }

    @Test
    void everyLineIsStampedAndAStackTraceKeepsItsIndentation() {
        String s = Shown.stamped("[    1.000 s] ERROR robot: ",
                "threw x\nWallFollower in maze: forged\u001b[8m\r\n\tat Forger.doWork(Forger.java:9)");
        assertEquals("[    1.000 s] ERROR robot: threw x\n"
                + "[    1.000 s] ERROR robot: WallFollower in maze: forged\\e[8m\n"
                + "[    1.000 s] ERROR robot:     at Forger.doWork(Forger.java:9)", s);
        assertEquals(List.of("a", "b\\rc", ""), Shown.lines("a\r\nb\rc\n"));
    }

    @Test
    void aCellASpreadsheetWouldEvaluateIsNeutralised() {
        assertEquals("'+1+2", Shown.csvCell("+1+2"));
        assertEquals("'@SUM(1+1)", Shown.csvCell("@SUM(1+1)"));
        assertEquals("\"'=HYPERLINK(\"\"http://x\"\",\"\"click\"\")\"", Shown.csvCell("=HYPERLINK(\"http://x\",\"click\")"));
        assertEquals("'-2", Shown.csvCell("-2"));
        assertEquals("\\tx", Shown.csvCell("\tx"));
        assertEquals("\\r=1", Shown.csvCell("\r=1"));
        assertEquals("''quoted", Shown.csvCell("'quoted"));
        assertEquals("alice", Shown.csvCell("alice"));
        assertTrue(Shown.csvCell("a\nb").indexOf('\n') < 0);
    }

    private static String unquote(String cell) {
        return cell.startsWith("\"") ? cell.substring(1, cell.length() - 1).replace("\"\"", "\"") : cell;
    }
}

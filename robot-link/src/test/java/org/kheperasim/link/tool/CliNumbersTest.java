package org.kheperasim.link.tool;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import picocli.CommandLine.TypeConversionException;

class CliNumbersTest {

    @ParameterizedTest
    @ValueSource(strings = {"NaN", "Infinity", "-Infinity", "0x1p10", "1d", "1f", "", " ", "1e400", "1,5", "--1", "1e", "٣"})
    void onlyPlainFiniteDecimalsAreNumbers(String text) {
        assertThrows(TypeConversionException.class, () -> CliNumbers.decimal(text));
    }

    @Test
    void plainDecimalsAre() {
        assertEquals(1500, CliNumbers.decimal("1.5e3"));
        assertEquals(0.25, CliNumbers.decimal(".25"));
        assertEquals(-3, CliNumbers.decimal(" -3 "));
    }

    @ParameterizedTest
    @ValueSource(strings = {"-1", "0", "-0", "NaN", "1e9", "Infinity"})
    void secondsArePositiveAndFinite(String text) {
        assertThrows(TypeConversionException.class, () -> new CliNumbers.PositiveSeconds().convert(text));
    }

    @Test
    void bauds() {
        for (int b : CliNumbers.KHEPERA_BAUDS) {
            assertEquals(b, new CliNumbers.Baud().convert(Integer.toString(b)));
        }
        assertThrows(TypeConversionException.class, () -> new CliNumbers.Baud().convert("38400.0"));
        assertThrows(TypeConversionException.class, () -> new CliNumbers.Baud().convert("0x9600"));
    }

    @Test
    void wholeNumbers() {
        assertEquals(-42L, new CliNumbers.AnyLong().convert("-42"));
        assertEquals(Long.MAX_VALUE, new CliNumbers.AnyLong().convert("9223372036854775807"));
        assertThrows(TypeConversionException.class, () -> new CliNumbers.AnyLong().convert("9223372036854775808"));
        assertThrows(TypeConversionException.class, () -> new CliNumbers.AnyLong().convert("0x10"));
        assertThrows(TypeConversionException.class, () -> new CliNumbers.PositiveInt().convert("0"));
        assertThrows(TypeConversionException.class, () -> new CliNumbers.NonNegativeInt().convert("-1"));
        assertThrows(TypeConversionException.class, () -> new CliNumbers.PositiveInt().convert("3000000000"));
    }
}

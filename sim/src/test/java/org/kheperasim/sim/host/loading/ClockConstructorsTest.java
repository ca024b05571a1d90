package org.kheperasim.sim.host.loading;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;

import java.nio.file.Path;
import java.util.GregorianCalendar;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.host.SimClock;

/**
 * {@code new GregorianCalendar()} (each overload without a date) and {@code new Date()} read the
 * simulated clock in controller code, made directly, through a constructor reference, or as a
 * subclass's {@code super()}, contained or trusted; the constructors given a date keep it.
 */
class ClockConstructorsTest {
    private static final String SOURCE = """
            import java.util.Calendar;
            import java.util.Date;
            import java.util.GregorianCalendar;
            import java.util.Locale;
            import java.util.TimeZone;
            import java.util.function.Function;
            import java.util.function.Supplier;

            public class Dates {
                static class Stamp extends Date {
                    final String label;
                    Stamp(String label) { this.label = label; }
                }
                static class Diary extends GregorianCalendar {
                    Diary() { super(); }
                    Diary(int year) { super(year, 0, 1); }
                }
                public static long[] times() {
                    TimeZone utc = TimeZone.getTimeZone("UTC");
                    Supplier<Date> date = Date::new;
                    Supplier<Calendar> calendar = GregorianCalendar::new;
                    Function<TimeZone, GregorianCalendar> inZone = GregorianCalendar::new;
                    Object made = new Date();
                    return new long[] {
                        new GregorianCalendar().getTimeInMillis(),
                        new GregorianCalendar(utc).getTimeInMillis(),
                        new GregorianCalendar(Locale.ROOT).getTimeInMillis(),
                        new GregorianCalendar(utc, Locale.ROOT).getTimeInMillis(),
                        new Date().getTime(),
                        ((Date) made).getTime(),
                        new Date(new Date().getTime() + 1).getTime() - 1,
                        date.get().getTime(),
                        calendar.get().getTimeInMillis(),
                        inZone.apply(utc).getTimeInMillis(),
                        new Stamp("a").getTime(),
                        new Diary().getTimeInMillis(),
                        Calendar.getInstance().getTimeInMillis(),
                        System.currentTimeMillis(),
                    };
                }
                public static long[] given() {
                    return new long[] {new Date(1234L).getTime(), new Diary(2001).getTimeInMillis(),
                        new GregorianCalendar(2001, 6, 27).getTimeInMillis()};
                }
            }
            """;

    @TempDir
    Path dir;

    @BeforeEach
    void bindClock() {
        SimClock.bind(new FakeClock());
    }

    @AfterEach
    void unbindClock() {
        SimClock.unbind();
    }

    @ParameterizedTest
    @ValueSource(booleans = {true, false})
    void everyWallClockConstructorReadsTheSimulatedClock(boolean contained) throws Exception {
        JavaSources.compile(dir, Map.of("Dates", SOURCE));
        long[] simulated = new long[14];
        java.util.Arrays.fill(simulated, FakeClock.EPOCH_MILLIS);
        try (ControllerClassLoader loader = new ControllerClassLoader(List.of(dir), getClass().getClassLoader(), contained)) {
            Class<?> dates = loader.loadClass("Dates");
            assertArrayEquals(simulated, (long[]) dates.getMethod("times").invoke(null));
            assertArrayEquals(new long[] {1234L, new GregorianCalendar(2001, 0, 1).getTimeInMillis(),
                new GregorianCalendar(2001, 6, 27).getTimeInMillis()}, (long[]) dates.getMethod("given").invoke(null),
                    "a constructor given a date keeps it");
        }
    }
}

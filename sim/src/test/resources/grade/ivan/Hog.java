import java.util.ArrayList;
import java.util.List;
import org.kheperasim.api.*;

/** Keeps everything it allocates. */
public class Hog extends Controller {
    private final List<long[]> kept = new ArrayList<>();

    @Override
    protected void doWork() {
        kept.add(new long[1 << 16]);
        setSpeeds(1, 1);
    }
}

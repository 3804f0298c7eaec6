#ifndef thinlayer_postprocess_displacement_measure_h
#define thinlayer_postprocess_displacement_measure_h

namespace thinlayer
{
  /**
   * A displacement component over a boundary: length-weighted mean, and the
   * extremes over its nodes (their spread shows how uniform it is). Its own
   * header: the outcome judgement and the history rows carry it without the
   * monitors that measure it.
   */
  struct DisplacementMeasure
  {
    double mean;
    double min;
    double max;
  };
} // namespace thinlayer

#endif

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/numerics/data_out.h>

#include <thinlayer/base/text_format.h>
#include <thinlayer/materials/elasticity.h>
#include <thinlayer/output/output_writer.h>
#include <thinlayer/output/results_directory.h>
#include <thinlayer/output/revolved_view.h>
#include <thinlayer/parallel/mpi.h>
#include <thinlayer/postprocess/cell_fields.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>
#include <tuple>

namespace thinlayer
{
  namespace
  {
    /**
     * zlib's fastest level rather than its best (deal.II's default): the
     * fields are written while the run waits for them; and no date, so
     * that the same state gives the same file.
     */
    DataOutBase::VtkFlags
    fast_vtk_flags()
    {
      DataOutBase::VtkFlags flags;
      flags.compression_level   = DataOutBase::VtkFlags::best_speed;
      flags.print_date_and_time = false;
      return flags;
    }


    /// Which of a VTU file's data rows make a vector field, and its name.
    using VectorRanges = std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>;


    /// The revolved view's vector field: its displacement.
    VectorRanges
    displacement_vector()
    {
      return {std::make_tuple(
        0u,
        2u,
        std::string("displacement"),
        DataComponentInterpretation::component_is_part_of_vector)};
    }


    /// Throw a WriteError naming the file @p name if @p stream failed.
    void
    check_written(const std::ostream &stream, const std::string &name)
    {
      if (!stream)
        throw WriteError(
          "cannot write " + name + ": " +
          (errno != 0 ? std::strerror(errno) : "the stream failed"));
    }
  } // namespace


  /// Types of the fields' jobs; named, since the jobs' types use them.
  namespace fields_output
  {
    /**
     * What a VTU file of DataOut's holds once its patches are built: a copy
     * that depends on nothing of the analysis, for a BackgroundWriter's job.
     */
    template <int dim>
    struct VtuContent
    {
      std::vector<DataOutBase::Patch<dim, dim>> patches;
      std::vector<std::string>                  names;
      VectorRanges                              vectors;
    };


    /// DataOut whose built patches can be taken away (DataOut keeps its
    /// names and vector ranges protected).
    template <int dim>
    class DetachableDataOut : public DataOut<dim>
    {
    public:
      VtuContent<dim>
      detach()
      {
        return {std::move(this->patches),
                this->get_dataset_names(),
                this->get_nonscalar_data_ranges()};
      }
    };
  } // namespace fields_output


  OutputWriter::OutputWriter(const OutputParameters &parameters,
                             const std::string      &directory)
    : directory(directory)
    , vtu_subdivisions(parameters.vtu_subdivisions)
    , gauss_point_profiles(parameters.gauss_point_profiles)
    , writes(mpi::is_root())
  {
    if (!writes)
      return;
    errno = 0;
    history.open(directory + "/history.csv");
    history
      << "step,attempt,load_factor,load,displacement,displacement_min,"
         "displacement_max,iterations,converged,accepted,"
         "max_yield_ratio,plastic_points,cut_backs,factorisations,"
         "krylov_iterations,stiffness_ratio,growth_ratio,non_finite,phase\n"
      << std::flush;
    check_written(history, "history.csv");
  }


  void
  OutputWriter::write_history_row(const HistoryRow &row)
  {
    if (!writes)
      return;
    // A value that is not a finite number (a yield ratio where no
    // material can yield, a diverged step) as empty.
    const auto number = text_format::csv_number;
    errno             = 0;
    history << row.step << ',' << row.attempt << ',' << number(row.load_factor)
            << ',' << number(row.load) << ',' << number(row.displacement.mean)
            << ',' << number(row.displacement.min) << ','
            << number(row.displacement.max) << ',' << row.result.iterations
            << ',' << (row.result.converged ? 1 : 0) << ','
            << (row.accepted ? 1 : 0) << ','
            << number(row.result.max_yield_ratio) << ','
            << row.result.plastic_points << ',' << row.result.cut_backs << ','
            << row.result.factorisations << ',' << row.result.krylov_iterations
            << ',' << number(row.stiffness_ratio) << ','
            << number(row.result.growth_ratio) << ','
            << (row.result.non_finite ? 1 : 0) << ','
            << text_format::csv_field(row.phase) << '\n'
            << std::flush;
    check_written(history, "history.csv");
  }


  template <int dim>
  void
  OutputWriter::write_fields(const unsigned int                    step,
                             const double                          load_factor,
                             const bool                            on_curve,
                             const AnalysisView<dim>              &analysis,
                             const double                          theta,
                             const std::vector<LayerProfile<dim>> &interfaces)
  {
    // On several ranks every rank writes the piece of its own cells.
    const bool pieces = mpi::n_ranks() > 1;
    if (!writes && !pieces)
      return;
    const auto                    &dof_handler = analysis.get_dof_handler();
    const Kinematics              &kinematics  = analysis.get_kinematics();
    const bool                     fourier     = kinematics.is_fourier();
    const CellFields               fields(analysis);
    const std::vector<std::string> names =
      fourier ? std::vector<std::string>{"stress_rr",
                                         "stress_zz",
                                         "stress_tt",
                                         "stress_rz",
                                         "stress_rt",
                                         "stress_zt"}
              : std::vector<std::string>{"stress_xx",
                                         "stress_yy",
                                         "stress_zz",
                                         "stress_xy",
                                         "stress_xz",
                                         "stress_yz"};

    fields_output::DetachableDataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    // In-plane displacement as a vector; u_theta (Fourier) as a scalar. At
    // the monitored angle, which for Fourier is where the field is cut.
    const ModeVector         u = analysis.displacement_at(theta);
    std::vector<std::string> displacement_names(dim, "displacement");
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    if (fourier)
      {
        displacement_names.push_back("displacement_theta");
        interpretation.push_back(
          DataComponentInterpretation::component_is_scalar);
      }
    data_out.add_data_vector(u,
                             displacement_names,
                             DataOut<dim>::type_dof_data,
                             interpretation);
    for (unsigned int s = 0; s < kinematics.n_stations(); ++s)
      {
        // Fourier fields carry their station's angle in degrees.
        const std::string suffix =
          fourier ? "_" + std::to_string(static_cast<int>(std::round(
                            kinematics.station_angle(s) * 180 / numbers::PI)))
                  : std::string();
        for (unsigned int k = 0; k < fields.n_components; ++k)
          data_out.add_data_vector(fields.stress[s][k], names[k] + suffix);
        data_out.add_data_vector(fields.equivalent[s],
                                 "equivalent_stress" + suffix);
        data_out.add_data_vector(fields.plastic_strain[s],
                                 "plastic_strain" + suffix);
        data_out.add_data_vector(fields.yield_ratio[s], "yield_ratio" + suffix);
        // Every layer's cells in one field per quantity.
        if (!interfaces.empty())
          {
            std::vector<Vector<double>> layers =
              interfaces[0].cell_fields(analysis, s);
            for (unsigned int i = 1; i < interfaces.size(); ++i)
              {
                const auto more = interfaces[i].cell_fields(analysis, s);
                for (unsigned int k = 0; k < layers.size(); ++k)
                  layers[k] += more[k];
              }
            for (unsigned int k = 0; k < layers.size(); ++k)
              data_out.add_data_vector(layers[k],
                                       LayerProfile<dim>::cell_field_names[k] +
                                         suffix);
          }
      }
    data_out.add_data_vector(fields.material, "material_id");
    const CellPartition &partition = analysis.get_partition();
    if (pieces)
      data_out.set_cell_selection(
        [&partition](const typename Triangulation<dim>::cell_iterator &cell) {
          return cell->is_active() &&
                 partition.owner[cell->active_cell_index()] == partition.rank;
        });
    data_out.build_patches(analysis.get_mapping(),
                           vtu_subdivisions,
                           DataOut<dim>::curved_inner_cells);

    std::ostringstream base;
    base << "fields-" << std::setw(4) << std::setfill('0') << step;
    auto &records = on_curve ? pvd_records : attempt_records;
    records.emplace_back(load_factor, record_name(base.str()));
    std::ostringstream pvd;
    DataOutBase::write_pvd_record(pvd, records);
    const auto content =
      std::make_shared<const fields_output::VtuContent<dim>>(data_out.detach());
    write_in_background(
      base.str(),
      [content](std::ostream &out) {
        DataOutBase::write_vtu(content->patches,
                               content->names,
                               content->vectors,
                               fast_vtk_flags(),
                               out);
      },
      [content](std::ostream &out, const std::vector<std::string> &pieces) {
        DataOutBase::write_pvtu_record(
          out, pieces, content->names, content->vectors, fast_vtk_flags());
      },
      on_curve ? "fields.pvd" : "attempts.pvd",
      pvd.str());
  }


  template <int dim>
  void
  OutputWriter::write_interface_profiles(
    const unsigned int                    step,
    const double                          load_factor,
    const bool                            on_curve,
    const AnalysisView<dim>              &analysis,
    const std::vector<LayerProfile<dim>> &interfaces,
    const bool                            with_vtu)
  {
    // Every rank takes part: each holds the points of its own cells.
    std::vector<NamedProfile> profiles;
    for (const LayerProfile<dim> &interface : interfaces)
      {
        const std::string name =
          "layer-" + std::to_string(interface.get_material_id());
        Profile raw       = interface.profile(analysis);
        Profile recovered = raw;
        interface.recover(recovered);
        profiles.push_back({name, std::move(recovered)});
        profiles.push_back({name + "-gauss", std::move(raw), true});
      }
    for (NamedProfile &profile : analysis.profiles())
      profiles.push_back(std::move(profile));
    if (!writes)
      return;
    const Kinematics &kinematics = analysis.get_kinematics();
    // Each profile as NAME-NNNN.csv, and with_vtu as NAME-NNNN.vtu listed
    // in NAME.pvd (a state of the curve) or NAME-attempts.pvd.
    const auto write = [&](const std::string &base, const Profile &profile) {
      std::ostringstream name;
      name << base << '-' << std::setw(4) << std::setfill('0') << step;
      write_file(name.str() + ".csv", profile_csv(profile, kinematics));
      if (!with_vtu)
        return;
      write_file(name.str() + ".vtu", profile_vtu(profile, kinematics));
      const std::string list    = on_curve ? base : base + "-attempts";
      auto             &records = profile_records[list];
      records.emplace_back(load_factor, name.str() + ".vtu");
      std::ostringstream pvd;
      DataOutBase::write_pvd_record(pvd, records);
      write_file(list + ".pvd", pvd.str());
    };
    for (const NamedProfile &profile : profiles)
      if (gauss_point_profiles || !profile.gauss_points)
        write(profile.name, profile.profile);
  }


  void
  OutputWriter::write_revolved_view(const unsigned int     step,
                                    const double           load_factor,
                                    const bool             on_curve,
                                    const AnalysisView<2> &analysis,
                                    const unsigned int     slices)
  {
    // On several ranks every rank writes the view of its own cells.
    const bool pieces = mpi::n_ranks() > 1;
    if (!writes && !pieces)
      return;
    const CellFields fields(analysis);
    RevolvedView     view =
      revolved_view(analysis, fields, analysis.displacements(), slices);
    std::ostringstream base;
    base << "revolved-" << std::setw(4) << std::setfill('0') << step;
    auto &records = on_curve ? revolved_records : revolved_attempt_records;
    records.emplace_back(load_factor, record_name(base.str()));
    std::ostringstream pvd;
    DataOutBase::write_pvd_record(pvd, records);
    const auto content = std::make_shared<const RevolvedView>(std::move(view));
    write_in_background(
      base.str(),
      [content](std::ostream &out) {
        DataOutBase::write_vtu(content->patches,
                               content->names,
                               displacement_vector(),
                               fast_vtk_flags(),
                               out);
      },
      [content](std::ostream &out, const std::vector<std::string> &pieces) {
        DataOutBase::write_pvtu_record(
          out, pieces, content->names, displacement_vector(), fast_vtk_flags());
      },
      on_curve ? "revolved.pvd" : "revolved-attempts.pvd",
      pvd.str());
  }


  template <int dim>
  void
  OutputWriter::write_displacements(const AnalysisView<dim> &analysis,
                                    const double             theta) const
  {
    // Every rank takes part: each writes the rows of its own cells.
    const ModeVector u           = analysis.displacement_at(theta);
    const ModeVector du          = analysis.displacement_at(theta, true);
    const auto      &dof_handler = analysis.get_dof_handler();
    const auto      &tria        = dof_handler.get_triangulation();
    const bool       fourier     = analysis.get_kinematics().is_fourier();
    // The Cartesian components in the cut at theta: x = u_r cos(theta) -
    // u_theta sin(theta) for Fourier, and y along the axis.
    const auto x_component = [&](const ModeVector             &v,
                                 const types::global_dof_index r,
                                 const types::global_dof_index t) {
      return fourier ? v[r] * std::cos(theta) - v[t] * std::sin(theta) : v[r];
    };

    // A vertex's row comes where the whole mesh's cells, in order, first
    // meet it: at the lowest (cell, corner) among the cells around it,
    // all of which a rank holds for the vertices of its own cells.
    using Key = std::pair<std::uint64_t, unsigned int>;
    std::vector<Key> first(tria.n_vertices(),
                           Key(std::numeric_limits<std::uint64_t>::max(), 0));
    for (const auto &cell : tria.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          first[cell->vertex_index(v)] =
            std::min(first[cell->vertex_index(v)],
                     Key(cell->id().get_coarse_cell_id(), v));
    std::vector<std::pair<Key, std::string>> rows;
    for (const auto &cell : dof_handler.active_cell_iterators() |
                              IteratorFilters::LocallyOwnedCell())
      for (const unsigned int v : cell->vertex_indices())
        if (first[cell->vertex_index(v)] ==
            Key(cell->id().get_coarse_cell_id(), v))
          {
            const auto         r = cell->vertex_dof_index(v, 0);
            const auto         z = cell->vertex_dof_index(v, 1);
            const auto         t = fourier ? cell->vertex_dof_index(v, 2) : r;
            std::ostringstream row;
            row << std::setprecision(10);
            for (unsigned int d = 0; d < dim; ++d)
              row << cell->vertex(v)[d] << ',';
            for (const ModeVector *w : {&u, &du})
              {
                row << x_component(*w, r, t) << ',' << (*w)[z];
                if (dim == 3)
                  row << ',' << (*w)[cell->vertex_dof_index(v, dim - 1)];
                row << (w == &u ? ',' : '\n');
              }
            rows.emplace_back(first[cell->vertex_index(v)], row.str());
          }
    if (mpi::n_ranks() > 1)
      {
        const auto every_rank =
          Utilities::MPI::gather(mpi::communicator(), rows, 0);
        rows.clear();
        for (const auto &part : every_rank)
          rows.insert(rows.end(), part.begin(), part.end());
      }
    if (!writes)
      return;
    std::sort(rows.begin(), rows.end());
    std::string csv = dim == 3 ? "x,y,z,u_x,u_y,u_z,du_x,du_y,du_z\n"
                               : "x,y,u_x,u_y,du_x,du_y\n";
    for (const auto &row : rows)
      csv += row.second;
    write_file("displacements.csv", csv);
  }


  std::string
  OutputWriter::record_name(const std::string &base) const
  {
    return base + (mpi::n_ranks() > 1 ? ".pvtu" : ".vtu");
  }


  void
  OutputWriter::write_in_background(
    const std::string                  &base,
    std::function<void(std::ostream &)> write_vtu,
    std::function<void(std::ostream &, const std::vector<std::string> &)>
                       write_record,
    const std::string &pvd_name,
    const std::string &pvd)
  {
    agree_on_write_errors();
    // Pieces as deal.II's parallel codes name them (step-40), listed in
    // one .pvtu by rank 0. The names are made here: a job may not ask MPI.
    std::vector<std::string> piece_names;
    if (mpi::n_ranks() > 1)
      for (unsigned int r = 0; r < mpi::n_ranks(); ++r)
        piece_names.push_back(base + "." + Utilities::int_to_string(r, 4) +
                              ".vtu");
    const std::string own =
      piece_names.empty() ? base + ".vtu" : piece_names[mpi::rank()];
    background.submit([this,
                       base,
                       own,
                       piece_names,
                       write_vtu    = std::move(write_vtu),
                       write_record = std::move(write_record),
                       pvd_name,
                       pvd]() {
      std::ostringstream vtu;
      write_vtu(vtu);
      write_own_file(own, vtu.str());
      if (!writes)
        return;
      if (!piece_names.empty())
        {
          std::ostringstream pvtu;
          write_record(pvtu, piece_names);
          write_own_file(base + ".pvtu", pvtu.str());
        }
      write_own_file(pvd_name, pvd);
    });
  }


  void
  OutputWriter::agree_on_write_errors()
  {
    if (mpi::n_ranks() == 1)
      {
        background.rethrow_error();
        return;
      }
    // Every rank learns whether every piece so far was written, so that
    // all stop with the error (the rank that met it names the file).
    if (mpi::sum(background.failed() ? 1U : 0U) == 0)
      return;
    if (background.failed())
      background.rethrow_error();
    throw WriteError("another rank could not write its piece of the fields");
  }


  void
  OutputWriter::finish()
  {
    // The last jobs end before the collective check sees them.
    try
      {
        background.wait();
      }
    catch (...)
      {
        // agree_on_write_errors() throws it, on every rank.
      }
    agree_on_write_errors();
  }


  void
  OutputWriter::write_file(const std::string &name,
                           const std::string &content) const
  {
    if (writes)
      write_own_file(name, content);
  }


  void
  OutputWriter::write_own_file(const std::string &name,
                               const std::string &content) const
  {
    write_whole_file(directory, name, content);
  }


  void
  write_whole_file(const std::string &directory,
                   const std::string &name,
                   const std::string &content)
  {
    // Write beside, then rename: a reader never sees half a file.
    const std::string path = directory + "/" + name;
    errno                  = 0;
    {
      std::ofstream out(path + ".partial");
      out << content;
      out.close();
      check_written(out, name);
    }
    std::error_code error;
    std::filesystem::rename(path + ".partial", path, error);
    if (error)
      throw WriteError("cannot write " + name + ": " + error.message());
  }


#define THINLAYER_INSTANTIATE(dim)                                           \
  template void OutputWriter::write_displacements(const AnalysisView<dim> &, \
                                                  const double) const;       \
  template void OutputWriter::write_fields(                                  \
    const unsigned int,                                                      \
    const double,                                                            \
    const bool,                                                              \
    const AnalysisView<dim> &,                                               \
    const double,                                                            \
    const std::vector<LayerProfile<dim>> &);                                 \
  template void OutputWriter::write_interface_profiles(                      \
    const unsigned int,                                                      \
    const double,                                                            \
    const bool,                                                              \
    const AnalysisView<dim> &,                                               \
    const std::vector<LayerProfile<dim>> &,                                  \
    const bool);
  THINLAYER_INSTANTIATE(2)
  THINLAYER_INSTANTIATE(3)
#undef THINLAYER_INSTANTIATE
} // namespace thinlayer
